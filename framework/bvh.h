// The framework's bounding volume hierarchy: 8-wide nodes, which keep the boxes of their (up to)
// eight children side by side, so that one plain loop tests a ray against all eight boxes: the
// compiler turns each line of it into SIMD instructions for several children at once (two 4-wide
// SSE instructions on any x86-64, NEON on ARM64; no intrinsics, no special flags; Scene compiles
// a second copy of the traversal for AVX2, one 8-wide instruction, which x86-64 CPUs that have
// it run: scene.cpp). The build is the textbook binary split by binned SAH (Wald 2007), used to
// make the wide nodes top-down as Embree's builder does: a node's items are split in two, then
// the child of largest surface area is split again, until the node has eight children or only
// leaves; each child that is not a leaf becomes a node the same way (bvh.cpp). The binary tree
// is never stored: the same nodes as building it whole and collapsing it, in 0.8 of the time.
//
// One wide node (256 bytes, four cache lines), children c0..c7:
//
//   corner[0][0] = x  | c0 | c1 | c2 | c3 | c4 | c5 | c6 | c7 |   the boxes, structure of arrays:
//   corner[0][1] = y  | c0 | c1 | c2 | c3 | c4 | c5 | c6 | c7 |   corner[side][axis][child], side 0
//   corner[0][2] = z  | c0 | c1 | c2 | c3 | c4 | c5 | c6 | c7 |   the lower corners, 1 the upper
//   corner[1][0..2]   |      the same for the upper corners      |
//   slot              | c0 | c1 | c2 | c3 | c4 | c5 | c6 | c7 |   (child, count) of each: inner
//                                                                 child: its index in nodes(),
//                                                                 count = kInner; leaf: its first
//                                                                 item and its number of items
//      (an unused slot is a leaf of 0 items whose box, both corners +inf, no ray reaches; a slot is
//      one 8-byte pair, so that a push copies it whole: 6 % fewer instructions for shadow rays)
//   (Child boxes quantised to 8 bits per plane on a grid of the node's, 128-byte nodes, cut the
//   cache misses by a third, made primary and incoherent rays 9-13 % slower and shadow rays no
//   faster: bench/README.md, issue 30.)
//
// Items are the caller's primitives in leaf order (item i is primitive order()[i]); a leaf is a
// run of consecutive items, so the caller can store what its primitive test reads in that order
// (Scene keeps a copy of each triangle there) and a leaf's test reads adjacent memory:
//
//      items   | leaf A: 3 | leaf B: 1 | leaf C: 4 | ...
//
// Traversal keeps a stack of (slot, entry distance): a node's children that the ray enters are
// pushed farthest first, so the nearest is taken next; a child whose entry distance lies beyond
// the closest hit found since it was pushed is dropped without being looked at.
#pragma once
#include <cstdint>
#include <vector>
#include "geometry.h"
#include "large_pages.h"

namespace ps {

struct alignas(64) WideNode {
    static constexpr int kWidth = 8;
    static constexpr uint32_t kInner = 0xffffffffu;  // count of an inner child
    float corner[2][3][kWidth];
    struct Slot {
        uint32_t child, count;
    } slot[kWidth];
    AABB box(int c) const {
        AABB b;
        b.lo = Vec3(corner[0][0][c], corner[0][1][c], corner[0][2][c]);
        b.hi = Vec3(corner[1][0][c], corner[1][1][c], corner[1][2][c]);
        return b;
    }
};

// What the slab test needs of a ray, computed once per ray: the origin, 1/d (+-inf along an
// axis-parallel direction; d + 0 turns a -0 into +0, so such an axis always gives +inf), 1/d
// grown by 1 + 2 gamma(4) for the far planes (see intersectBoxes) and, per axis, which plane of
// a slab the ray meets first (the lower one when d >= 0).
struct BoxRay {
    float org[3], inv[3], invFar[3];
    int nearSide[3];  // the corner (0 lower, 1 upper) whose plane the ray meets first, per axis
    explicit BoxRay(const Ray& r) {
        constexpr float kGrow = 1.0f + 2.0f * 4.0f * 0x1p-24f / (1.0f - 4.0f * 0x1p-24f);
        for (int a = 0; a < 3; ++a) {
            org[a] = r.o[a];
            inv[a] = 1.0f / (r.d[a] + 0.0f);
            invFar[a] = inv[a] * kGrow;
            nearSide[a] = inv[a] < 0.0f;
        }
    }
};

// Where a ray enters each of a node's boxes and whether it meets the box within [0, tMax].
struct BoxHits {
    float enter[WideNode::kWidth];
    int hit[WideNode::kWidth];
};

class BVH {
public:
    static constexpr int kBins = 16;
    static constexpr int kMaxLeafSize = 4;      // the SAH may keep a range of at most this many whole
    static constexpr int kMaxWideLeafSize = 6;  // a subtree of at most this many becomes one leaf
    static constexpr int kMaxDepth = 100;       // deeper subtrees become leaves; bounds the stack
    // Boxes entered up to tMax * kCullGrow are visited (see traverse): 2^-16 covers the box
    // entry's rounding (gamma(3)) and the triangle test's t (a few gamma) with room to spare.
    static constexpr float kCullGrow = 1.0f + 0x1p-16f;

    // Builds over the primitives' boxes; primitive i of the caller is reported as i.
    void build(const std::vector<AABB>& primBoxes);

    using WideNodes = std::vector<WideNode, LargePageAllocator<WideNode>>;  // on 2 MB pages when large
    const WideNodes& nodes() const { return nodes_; }
    const std::vector<uint32_t>& order() const { return order_; }  // item -> primitive
    AABB bounds() const { return bounds_; }
    int depth() const { return depth_; }  // levels of wide nodes (root = 1; 0 when empty)

    // Visits the items whose boxes the ray reaches, nearest box first. hitItem(item, ray) tests
    // one item (primitive order()[item]) and, on a closer hit, shortens ray.tMax and returns
    // true. With anyHit the traversal stops at the first hit.
    template <class HitItem>
    bool traverse(Ray& ray, bool anyHit, HitItem&& hitItem) const;

private:
    struct Items;  // the build's working copy of the items (bvh.cpp)
    struct Range;  // a run of items the build may split (bvh.cpp)
    bool split(Items& items, const Range& range, Range& left, Range& right);
    uint32_t buildNode(Items& items, const Range& range, int depth);
    static void setChild(WideNode& w, int k, const AABB& box, uint32_t child, uint32_t count);
    WideNodes nodes_;
    std::vector<uint32_t> order_;
    AABB bounds_;
    int depth_ = 0;
};

// The slab test of one ray against all of a node's boxes at once: GCC (-O3, the Release default;
// `-fopt-info-vec` reports "loop vectorized" for this line) and Clang turn the loop over the
// children into 4-wide SIMD instructions, each line of its body one instruction per four boxes.
// No early exit, no branch: every child is tested, the unused ones too. Along each axis the ray
// meets the near plane first (the lower one when d >= 0), so no min/max of the two is needed.
// The far distance is computed with 1/d grown by 1 + 2 gamma(4) (four roundings: the reciprocal,
// the growth, the subtraction, the product), so that float rounding never misses a box (Ize 2013,
// who grows the far distance itself by 1 + 2 gamma(3)). NaN-safe: a slab gives NaN only for a
// ray lying in one of its planes (0 * inf, d = +0 after BoxRay), and NaN compares false, so that
// plane leaves t0 or t1 as it was (the ray is in the slab). t0 only grows and t1 only shrinks:
// one test at the end.
inline BoxHits intersectBoxes(const WideNode& n, const BoxRay& r, float tMax) {
    const float *near[3], *far[3];
    for (int a = 0; a < 3; ++a) {
        near[a] = n.corner[r.nearSide[a]][a];  // (an index, not a branch, per node)
        far[a] = n.corner[1 - r.nearSide[a]][a];
    }
    BoxHits h;
    for (int c = 0; c < WideNode::kWidth; ++c) {
        float t0 = 0.0f, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const float tNear = (near[a][c] - r.org[a]) * r.inv[a];
            const float tFar = (far[a][c] - r.org[a]) * r.invFar[a];
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
        }
        h.enter[c] = t0;
        h.hit[c] = t0 <= t1;
    }
    return h;
}

template <class HitItem>
bool BVH::traverse(Ray& ray, bool anyHit, HitItem&& hitItem) const {
    if (nodes_.empty()) return false;
    const BoxRay boxRay(ray);
    struct Entry {
        WideNode::Slot slot;  // the child
        float enter;          // where the ray enters its box
    };
    // Each level leaves at most kWidth - 1 siblings behind, and the last push writes one more.
    Entry stack[(WideNode::kWidth - 1) * kMaxDepth + 2];
    int top = 0;
    stack[top++] = {{0, WideNode::kInner}, 0.0f};
    bool hit = false;
    while (top > 0) {
        --top;
        // Beyond the closest hit found since it was pushed (any hit: tMax never changes, and the
        // box test has already left out boxes beyond it). Both tests compare with tMax grown by
        // kCullGrow: where a ray meets triangles of two leaves at one point (a shared vertex or
        // edge), the triangle test's t of the nearer can lie below the other's by a float step
        // while the nearer leaf's box entry, rounded up, lies above it; left out, that leaf would
        // lose the closer hit (tests/framework/test_bvh.cpp, rays through a mesh's vertices).
        const float tCull = ray.tMax * kCullGrow;
        if (!anyHit && stack[top].enter > tCull) continue;
        // (Read field by field: a copy of the whole entry went through memory, 6 % of the time.)
        const uint32_t child = stack[top].slot.child, count = stack[top].slot.count;
        if (count != WideNode::kInner) {
            for (uint32_t i = child; i < child + count; ++i) {
                if (hitItem(i, ray)) {
                    hit = true;
                    if (anyHit) return true;
                }
            }
            continue;
        }
        const WideNode& n = nodes_[child];
        const BoxHits h = intersectBoxes(n, boxRay, tCull);
        // Push the children the ray enters. Any hit: in any order, each child written and kept
        // only if hit (no branch per child, which incoherent rays would mispredict). Closest
        // hit: sorted by entry distance, the nearest on top, so that it is visited next; the
        // loop unrolled (GCC and Clang read the pragma, others ignore it): eight branches of
        // their own predict better than one, and primary rays got 6 % faster (bench/README.md).
        const int bottom = top;
        if (anyHit) {
            for (int c = 0; c < WideNode::kWidth; ++c) {
                stack[top] = {n.slot[c], 0.0f};  // (enter unused)
                top += h.hit[c];
            }
            continue;
        }
#pragma GCC unroll 8
        for (int c = 0; c < WideNode::kWidth; ++c) {
            if (!h.hit[c]) continue;
            int j = top++;
            for (; j > bottom && stack[j - 1].enter < h.enter[c]; --j) stack[j] = stack[j - 1];
            stack[j] = {n.slot[c], h.enter[c]};
        }
    }
    return hit;
}

}  // namespace ps
