#include "bvh.h"
#include <numeric>

namespace ps {

void BVH::build(const std::vector<AABB>& primBoxes) {
    nodes_.clear();
    depth_ = 0;
    const uint32_t n = static_cast<uint32_t>(primBoxes.size());
    primIndex_.resize(n);
    std::iota(primIndex_.begin(), primIndex_.end(), 0u);
    if (n == 0) return;
    std::vector<AABB> boxes = primBoxes;
    std::vector<Vec3> centroids(n);
    for (uint32_t i = 0; i < n; ++i) centroids[i] = boxes[i].center();
    nodes_.reserve(2 * n);
    nodes_.emplace_back();
    buildNode(0, boxes, centroids, 0, n, 1);
}

// Builds the subtree over entries [begin, end) into nodes_[self], which the caller allocated.
void BVH::buildNode(uint32_t self, std::vector<AABB>& boxes, std::vector<Vec3>& centroids, uint32_t begin, uint32_t end,
                    int depth) {
    depth_ = std::max(depth_, depth);
    AABB box, cbox;
    for (uint32_t i = begin; i < end; ++i) {
        box.expand(boxes[i]);
        cbox.expand(centroids[i]);
    }
    nodes_[self].box = box;
    const uint32_t count = end - begin;
    auto makeLeaf = [&] {
        nodes_[self].first = begin;
        nodes_[self].count = static_cast<uint16_t>(count);
    };
    if (count <= 1 || depth >= kMaxDepth) {
        makeLeaf();
        return;
    }

    // Binned SAH (Wald 2007): kBins bins along each axis of the centroid box; the cost of a
    // split is A + A_left * N_left + A_right * N_right, of a leaf A * N (traversal and
    // intersection cost 1 each; A is this node's area).
    const float area = box.surfaceArea();
    float bestCost = kInf;
    int bestAxis = -1, bestSplit = -1;
    const Vec3 ext = cbox.extent();
    for (int axis = 0; axis < 3; ++axis) {
        if (!(ext[axis] > 0.0f)) continue;
        AABB binBox[kBins];
        uint32_t binCount[kBins] = {};
        const float scale = kBins / ext[axis];
        for (uint32_t i = begin; i < end; ++i) {
            int b = std::min(kBins - 1, static_cast<int>((centroids[i][axis] - cbox.lo[axis]) * scale));
            binBox[b].expand(boxes[i]);
            ++binCount[b];
        }
        float rightArea[kBins];
        uint32_t rightCount[kBins];
        AABB acc;
        uint32_t cnt = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.expand(binBox[b]);
            cnt += binCount[b];
            rightArea[b] = acc.surfaceArea();
            rightCount[b] = cnt;
        }
        acc = AABB();
        cnt = 0;
        for (int s = 1; s < kBins; ++s) {  // split between bin s-1 and s
            acc.expand(binBox[s - 1]);
            cnt += binCount[s - 1];
            if (cnt == 0 || rightCount[s] == 0) continue;
            float cost = area + acc.surfaceArea() * cnt + rightArea[s] * rightCount[s];
            if (cost < bestCost) {
                bestCost = cost;
                bestAxis = axis;
                bestSplit = s;
            }
        }
    }
    const float leafCost = area * count;
    uint32_t mid;
    if (bestAxis >= 0 && (bestCost < leafCost || count > kMaxLeafSize)) {
        const float scale = kBins / ext[bestAxis];
        uint32_t i = begin, j = end;
        while (i < j) {  // partition by bin
            int b = std::min(kBins - 1, static_cast<int>((centroids[i][bestAxis] - cbox.lo[bestAxis]) * scale));
            if (b < bestSplit) {
                ++i;
                continue;
            }
            --j;
            std::swap(boxes[i], boxes[j]);
            std::swap(centroids[i], centroids[j]);
            std::swap(primIndex_[i], primIndex_[j]);
        }
        mid = i;
        nodes_[self].axis = static_cast<uint16_t>(bestAxis);
    } else if (count <= kMaxLeafSize) {
        makeLeaf();
        return;
    } else {
        // All centroids coincide: split the list in half (any split is as good).
        mid = begin + count / 2;
        nodes_[self].axis = 0;
    }
    const uint32_t left = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[self].first = left;
    nodes_[self].count = 0;
    // The children are adjacent (right = left + 1): allocate both, then build each.
    buildNode(left, boxes, centroids, begin, mid, depth + 1);
    buildNode(left + 1, boxes, centroids, mid, end, depth + 1);
}

}  // namespace ps
