#include "bvh.h"
#include <numeric>

namespace ps {

namespace {
constexpr uint32_t kSplitSamples = 64;  // a larger node picks its split from a sample of its items
constexpr int kMinBins = 6;             // a range of N items gets min(kBins, kMinBins + N / 20) bins
static_assert(BVH::kBins <= 256, "itemBins keeps an item's bin along each axis in one byte");
constexpr uint32_t kNoNode = 0xffffffffu;  // buildNode's answer for a range that stays a leaf
}  // namespace

// The build's working copy of the items: their boxes, centroids and bins, moved by the
// partitions together with order_ (item -> primitive).
struct BVH::Items {
    std::vector<AABB> boxes;
    std::vector<Vec3> centroids;
    std::vector<uint32_t> bins;  // each item's bin along each axis, a byte each (see split)
};

// Items [begin, end): box bounds their boxes and cbox their centroids; depth is the range's
// depth in the binary tree of splits (the root 1); leaf: split was asked and kept it whole.
struct BVH::Range {
    AABB box, cbox;
    uint32_t begin = 0, end = 0;
    int depth = 1;
    bool leaf = false;
};

void BVH::build(const std::vector<AABB>& primBoxes) {
    nodes_.clear();
    depth_ = 0;
    bounds_ = AABB();
    const uint32_t n = static_cast<uint32_t>(primBoxes.size());
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    if (n == 0) return;
    Items items{primBoxes, std::vector<Vec3>(n), std::vector<uint32_t>(n)};
    Range root;
    root.end = n;
    for (uint32_t i = 0; i < n; ++i) {
        items.centroids[i] = items.boxes[i].center();
        root.box.expand(items.boxes[i]);
        root.cbox.expand(items.centroids[i]);
    }
    bounds_ = root.box;
    nodes_.reserve(n / 4 + 1);
    if (buildNode(items, root, 1) != kNoNode) return;
    // Items the root's split kept whole: a root with one leaf child.
    nodes_.resize(1);
    setChild(nodes_[0], 0, root.box, 0, n);
    for (int k = 1; k < WideNode::kWidth; ++k) setChild(nodes_[0], k, AABB(), 0, 0);
    depth_ = 1;
}

// Slot k of a wide node: an inner child (count = kInner, child = its index in nodes_), a leaf
// (child = its first item) or nothing: a leaf of no items whose box (lo = hi = +inf; also used
// for an empty box) no ray reaches.
void BVH::setChild(WideNode& w, int k, const AABB& box, uint32_t child, uint32_t count) {
    for (int a = 0; a < 3; ++a) {
        w.corner[0][a][k] = box.empty() ? kInf : box.lo[a];
        w.corner[1][a][k] = box.empty() ? kInf : box.hi[a];
    }
    w.slot[k] = {child, count};
}

// Splits range into left and right by binned SAH and returns true, or returns false when the
// range stays a leaf (one item, the depth limit, or a leaf that the SAH prefers). The children's
// boxes and centroid boxes are gathered on the way (see below): no pass over their items.
bool BVH::split(Items& items, const Range& range, Range& leftRange, Range& rightRange) {
    const uint32_t begin = range.begin, end = range.end, count = end - begin;
    if (count <= 1 || range.depth >= kMaxDepth) return false;
    const AABB &box = range.box, &cbox = range.cbox;
    std::vector<AABB>& boxes = items.boxes;
    std::vector<Vec3>& centroids = items.centroids;
    std::vector<uint32_t>& itemBins = items.bins;

    // Binned SAH (Wald 2007): bins along each axis of the centroid box; the cost of a
    // split is A + A_left * N_left + A_right * N_right, of a leaf A * N (traversal and
    // intersection cost 1 each; A is this node's area). Measured with bench/bvh_bench: a
    // traversal cost of 2 with leaves of up to 8 (fewer, larger leaves for the wide nodes) made
    // the Cornell box 1.6-2.4 times and the bunny's incoherent rays 1.3 times slower.
    // The three axes are binned in one pass over the items (each item read once, not once per
    // axis); an axis along which all centroids coincide gets scale 0 (all its items in bin 0)
    // and is not evaluated. With the skipped empty bins and the children's bounds below: the
    // same tree to the bit, built in 0.75 of the time (bunny 34 -> 25 ms; bench/README.md).
    // A range of N items gets min(kBins, 6 + N / 20) bins (Embree's rule, 4 + N / 20, with 6 for
    // 4): a small range's sweeps over mostly empty bins cost more than its items. The build takes
    // 0.81-0.84 of the time with 16 bins everywhere, the wide tree's SAH cost is 0.1 % lower and
    // callgrind counts of the traversal within 0.15 % (bunny, motorbike; 4 + N / 20: 0.78, but
    // SAH +0.2 %; bench/README.md).
    const int bins = std::min(kBins, kMinBins + static_cast<int>(count / 20));
    const float area = box.surfaceArea();
    const Vec3 ext = cbox.extent();
    float scale[3];
    for (int a = 0; a < 3; ++a) scale[a] = ext[a] > 0.0f ? bins / ext[a] : 0.0f;
    // A node of at least 2 * kSplitSamples items bins only every stride-th item (kSplitSamples
    // to 2 * kSplitSamples of them) along the three axes, to pick the axis; then it bins all its
    // items along that axis alone and picks the split from those bins (as exact there as
    // before). The tree changes (SAH cost within 0.2 %; callgrind counts of the traversal within
    // 0.15 % on the bunny), the build takes 0.9 of the time (bunny 26.9 -> 24.7 ms, motorbike
    // 126 -> 112 ms CPU). The split from the sample alone (the children's boxes gathered by the
    // partition) was faster still (0.86) but cost the traversal 1 % more instructions
    // (bench/README.md, issue 30). A node of fewer items bins them all along the three axes.
    const uint32_t stride = count >= 2 * kSplitSamples ? count / kSplitSamples : 1;
    AABB binBox[3][kBins];
    uint32_t binCount[3][kBins] = {};
    auto binItem = [&](uint32_t i, int a) {
        const int b = std::min(bins - 1, static_cast<int>((centroids[i][a] - cbox.lo[a]) * scale[a]));
        binBox[a][b].expand(boxes[i]);
        ++binCount[a][b];
        return static_cast<uint32_t>(b) << (8 * a);
    };
    if (stride == 1)
        for (uint32_t i = begin; i < end; ++i) itemBins[i] = binItem(i, 0) | binItem(i, 1) | binItem(i, 2);
    else
        for (uint32_t i = begin; i < end; i += stride)
            for (int a = 0; a < 3; ++a) binItem(i, a);
    float bestCost = kInf;
    int bestAxis = -1, bestSplit = -1;
    auto sweep = [&](int axis) {
        // An empty bin changes nothing: the sweeps skip it (a small node fills few of its bins),
        // and the split after it, which repeats the split before it (the same items on each
        // side), is not evaluated: the one before came first and wins the tie.
        float rightArea[kBins];
        uint32_t rightCount[kBins];
        AABB acc;
        uint32_t cnt = 0;
        float accArea = 0.0f;
        for (int b = bins - 1; b > 0; --b) {
            if (binCount[axis][b] != 0) {
                acc.expand(binBox[axis][b]);
                cnt += binCount[axis][b];
                accArea = acc.surfaceArea();
            }
            rightArea[b] = accArea;
            rightCount[b] = cnt;
        }
        acc = AABB();
        cnt = 0;
        for (int s = 1; s < bins; ++s) {  // split between bin s-1 and s
            if (binCount[axis][s - 1] == 0) continue;
            acc.expand(binBox[axis][s - 1]);
            cnt += binCount[axis][s - 1];
            if (rightCount[s] == 0) break;
            float cost = area + acc.surfaceArea() * cnt + rightArea[s] * rightCount[s];
            if (cost < bestCost) {
                bestCost = cost;
                bestAxis = axis;
                bestSplit = s;
            }
        }
    };
    for (int axis = 0; axis < 3; ++axis)
        if (ext[axis] > 0.0f) sweep(axis);
    if (stride > 1) {  // all items binned along the sample's axis (all three if it found no split)
        const int a0 = bestAxis >= 0 ? bestAxis : 0, a1 = bestAxis >= 0 ? bestAxis + 1 : 3;
        for (int a = a0; a < a1; ++a)
            for (int b = 0; b < bins; ++b) {
                binBox[a][b] = AABB();
                binCount[a][b] = 0;
            }
        for (uint32_t i = begin; i < end; ++i) {
            uint32_t packed = 0;
            for (int a = a0; a < a1; ++a) packed |= binItem(i, a);
            itemBins[i] = packed;
        }
        bestCost = kInf;
        bestAxis = -1;
        for (int axis = a0; axis < a1; ++axis)
            if (ext[axis] > 0.0f) sweep(axis);
    }
    const float leafCost = area * count;
    uint32_t mid;
    // What the children bound, with no pass of their own over the items: their boxes are the
    // unions of their bins, their centroids' boxes are gathered while partitioning. The
    // partition reads each item's bin as the binning stored it (itemBins: a byte per axis)
    // instead of computing it again: the same tree, built in 0.94 (bunny) and 0.98 (motorbike) of
    // the CPU time (medians of alternated runs; 0.9-1.0 each; bench/README.md, issue 30).
    AABB leftBox, leftCbox, rightBox, rightCbox;
    if (bestAxis >= 0 && (bestCost < leafCost || count > kMaxLeafSize)) {
        for (int b = 0; b < bins; ++b) (b < bestSplit ? leftBox : rightBox).expand(binBox[bestAxis][b]);
        const int shift = 8 * bestAxis;
        const uint32_t split = static_cast<uint32_t>(bestSplit);
        uint32_t i = begin, j = end;
        while (i < j) {  // partition by bin
            const uint32_t b = (itemBins[i] >> shift) & 0xffu;
            if (b < split) {
                leftCbox.expand(centroids[i]);
                ++i;
                continue;
            }
            --j;
            rightCbox.expand(centroids[i]);
            std::swap(boxes[i], boxes[j]);
            std::swap(centroids[i], centroids[j]);
            std::swap(order_[i], order_[j]);
            itemBins[i] = itemBins[j];  // item j's bin moves with it; item i's is not read again
        }
        mid = i;
    } else if (count <= kMaxLeafSize) {
        return false;
    } else {
        mid = begin + count / 2;  // all centroids coincide: split the list in half (any split is as good)
        for (uint32_t i = begin; i < end; ++i) {
            (i < mid ? leftBox : rightBox).expand(boxes[i]);
            (i < mid ? leftCbox : rightCbox).expand(centroids[i]);
        }
    }
    leftRange = {leftBox, leftCbox, begin, mid, range.depth + 1, false};
    rightRange = {rightBox, rightCbox, mid, end, range.depth + 1, false};
    return true;
}

// The index of range's wide node in nodes_, or kNoNode when range stays a leaf. It splits range
// in two, then splits the child of largest surface area (of those not known to be leaves) in
// two, until it has kWidth children or only leaves: the top levels of range's binary subtree,
// built as they are needed (Embree's BVHN builder). Then each child that is not a leaf becomes a
// wide node in turn, but for one of at most kMaxWideLeafSize items, which becomes a leaf as it
// is: a wide node of its own would cost a visit (four cache lines) to test two or three boxes
// (measured with bench/bvh_bench: up to 4 items, half as many nodes and incoherent and shadow
// rays 8-10 % faster than none; up to 6, about 4 % more; up to 8, more for those and 2 % less
// for primary rays). With the same splits, the nodes are those that building the whole binary
// tree and collapsing it gave (the earlier build), to the bit; only a leaf's items keep the
// order of the split that made it, where that tree split them further (a quarter of its
// splits, in no wide node). The build took 0.81 (bunny) and 0.84 (motorbike) of that one's CPU
// time (bench/README.md, issue 30).
uint32_t BVH::buildNode(Items& items, const Range& range, int depth) {
    Range kids[WideNode::kWidth];
    if (!split(items, range, kids[0], kids[1])) return kNoNode;
    depth_ = std::max(depth_, depth);
    int n = 2;
    while (n < WideNode::kWidth) {
        int open = -1;
        float openArea = -1.0f;
        for (int k = 0; k < n; ++k) {
            const float a = kids[k].box.surfaceArea();
            if (!kids[k].leaf && a > openArea) {
                openArea = a;
                open = k;
            }
        }
        if (open < 0) break;
        const Range parent = kids[open];
        if (split(items, parent, kids[open], kids[n])) ++n;
        else kids[open].leaf = true;
    }
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    for (int k = 0; k < WideNode::kWidth; ++k) {
        if (k >= n) {
            setChild(nodes_[index], k, AABB(), 0, 0);
            continue;
        }
        const Range& c = kids[k];
        const uint32_t count = c.end - c.begin;
        const uint32_t child = c.leaf || count <= kMaxWideLeafSize ? kNoNode : buildNode(items, c, depth + 1);
        if (child == kNoNode) setChild(nodes_[index], k, c.box, c.begin, count);
        else setChild(nodes_[index], k, c.box, child, WideNode::kInner);
    }
    return index;
}

}  // namespace ps
