#include "bvh.h"
#include <numeric>

namespace ps {

void BVH::build(const std::vector<AABB>& primBoxes) {
    nodes_.clear();
    depth_ = 0;
    bounds_ = AABB();
    const uint32_t n = static_cast<uint32_t>(primBoxes.size());
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    if (n == 0) return;
    // Stage 1: the binary tree.
    std::vector<AABB> boxes = primBoxes;
    std::vector<Vec3> centroids(n);
    for (uint32_t i = 0; i < n; ++i) centroids[i] = boxes[i].center();
    std::vector<BinaryNode> bin;
    bin.reserve(2 * n);
    bin.emplace_back();
    buildBinary(0, bin, boxes, centroids, 0, n, 1);
    bounds_ = bin[0].box;
    // Stage 2: the wide nodes. A binary tree that is a single leaf becomes a root with one child.
    if (bin[0].count == 0) {
        nodes_.reserve(bin.size() / 2);
        collapse(bin, 0, 1);
    } else {
        nodes_.resize(1);
        for (int k = 0; k < WideNode::kWidth; ++k) setChild(nodes_[0], k, k == 0 ? &bin[0] : nullptr, 0);
        depth_ = 1;
    }
}

// Slot k of a wide node: the binary node c (a leaf, or an inner node collapsed into nodes_[inner]),
// or nothing (c = nullptr): a leaf of no items whose box no ray reaches (lo = hi = +inf).
void BVH::setChild(WideNode& w, int k, const BinaryNode* c, uint32_t inner) {
    AABB box;
    box.lo = box.hi = Vec3(kInf);
    if (c && !c->box.empty()) box = c->box;
    for (int a = 0; a < 3; ++a) {
        w.lo[a][k] = box.lo[a];
        w.hi[a][k] = box.hi[a];
    }
    w.child[k] = !c ? 0 : c->count == 0 ? inner : c->first;
    w.count[k] = !c ? 0 : c->count == 0 ? WideNode::kInner : c->count;
}

// Builds the binary subtree over items [begin, end) into bin[self], which the caller allocated.
void BVH::buildBinary(uint32_t self, std::vector<BinaryNode>& bin, std::vector<AABB>& boxes,
                      std::vector<Vec3>& centroids, uint32_t begin, uint32_t end, int depth) {
    AABB box, cbox;
    for (uint32_t i = begin; i < end; ++i) {
        box.expand(boxes[i]);
        cbox.expand(centroids[i]);
    }
    bin[self].box = box;
    const uint32_t count = end - begin;
    auto makeLeaf = [&] {
        bin[self].first = begin;
        bin[self].count = count;
    };
    if (count <= 1 || depth >= kMaxDepth) {
        makeLeaf();
        return;
    }

    // Binned SAH (Wald 2007): kBins bins along each axis of the centroid box; the cost of a
    // split is A + A_left * N_left + A_right * N_right, of a leaf A * N (traversal and
    // intersection cost 1 each; A is this node's area). Measured with bench/bvh_bench: a
    // traversal cost of 2 with leaves of up to 8 (fewer, larger leaves for the wide nodes) made
    // the Cornell box 1.6-2.4 times and the bunny's incoherent rays 1.3 times slower.
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
            std::swap(order_[i], order_[j]);
        }
        mid = i;
    } else if (count <= kMaxLeafSize) {
        makeLeaf();
        return;
    } else {
        mid = begin + count / 2;  // all centroids coincide: split the list in half (any split is as good)
    }
    const uint32_t left = static_cast<uint32_t>(bin.size());
    bin.emplace_back();
    bin.emplace_back();
    bin[self].first = left;
    bin[self].count = 0;
    // The children are adjacent (right = left + 1): allocate both, then build each.
    buildBinary(left, bin, boxes, centroids, begin, mid, depth + 1);
    buildBinary(left + 1, bin, boxes, centroids, mid, end, depth + 1);
}

// Stage 2: the wide node of the binary inner node bin[self]. It starts with that node's two
// children and opens the inner child of largest surface area (replacing it by its own two
// children) until it has kWidth children or only leaves; then each inner child is collapsed
// in turn. Leaves keep their items, so the items' leaf order stays the binary tree's.
uint32_t BVH::collapse(const std::vector<BinaryNode>& bin, uint32_t self, int depth) {
    depth_ = std::max(depth_, depth);
    uint32_t kids[WideNode::kWidth] = {bin[self].first, bin[self].first + 1};
    int n = 2;
    while (n < WideNode::kWidth) {
        int open = -1;
        float openArea = -1.0f;
        for (int k = 0; k < n; ++k) {
            const BinaryNode& c = bin[kids[k]];
            if (c.count == 0 && c.box.surfaceArea() > openArea) {
                openArea = c.box.surfaceArea();
                open = k;
            }
        }
        if (open < 0) break;
        const uint32_t first = bin[kids[open]].first;
        kids[open] = first;
        kids[n++] = first + 1;
    }
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    for (int k = 0; k < WideNode::kWidth; ++k) {
        const BinaryNode* c = k < n ? &bin[kids[k]] : nullptr;
        const uint32_t inner = c && c->count == 0 ? collapse(bin, kids[k], depth + 1) : 0;
        setChild(nodes_[index], k, c, inner);  // after the recursion: nodes_ may have grown
    }
    return index;
}

}  // namespace ps
