// The framework's own bounding volume hierarchy: binned SAH build, flat node array (the two
// children of a node are adjacent), ordered stack traversal, closest hit and any hit.
#pragma once
#include <cstdint>
#include <vector>
#include "geometry.h"

namespace ps {

struct BVHNode {
    AABB box;
    uint32_t first = 0;  // inner node: index of the left child (right = first + 1);
                         // leaf: first entry in BVH::primIndex
    uint16_t count = 0;  // 0 for an inner node, number of primitives for a leaf
    uint16_t axis = 0;   // split axis of an inner node (ordered traversal)
};

class BVH {
public:
    static constexpr int kBins = 16;
    static constexpr int kMaxLeafSize = 4;
    static constexpr int kMaxDepth = 100;  // deeper subtrees become leaves; bounds the stack

    // Builds over the primitives' boxes; primitive i of the caller is reported as i.
    void build(const std::vector<AABB>& primBoxes);

    const std::vector<BVHNode>& nodes() const { return nodes_; }
    const std::vector<uint32_t>& primIndex() const { return primIndex_; }
    AABB bounds() const { return nodes_.empty() ? AABB() : nodes_[0].box; }
    int depth() const { return depth_; }

    // Visits primitives whose boxes the ray reaches, nearest child first.
    // hitPrim(primIndex, ray) tests one primitive and, on a closer hit, shortens ray.tMax and
    // returns true. With anyHit the traversal stops at the first hit.
    template <class HitPrim>
    bool traverse(Ray& ray, bool anyHit, HitPrim&& hitPrim) const;

private:
    void buildNode(uint32_t node, std::vector<AABB>& boxes, std::vector<Vec3>& centroids, uint32_t begin, uint32_t end,
                   int depth);
    std::vector<BVHNode> nodes_;
    std::vector<uint32_t> primIndex_;
    int depth_ = 0;
};

// Slab test; invDir may hold +-inf (axis-parallel rays). The 1 + 2*gamma(3) factor makes the
// test conservative in float (Ize 2013), so no box is missed by rounding.
// Branch-free (each ?: below is one minss/maxss): t0 only grows and t1 only shrinks, so testing
// t0 > t1 once at the end is the same as testing it after every axis, and incoherent rays do
// not pay a mispredicted branch per axis (bench/README.md).
inline bool intersectBox(const AABB& b, const Vec3& o, const Vec3& invDir, float tMax, float& tNear) {
    constexpr float kGrow = 1.0f + 2.0f * 3.0f * 0x1p-24f / (1.0f - 3.0f * 0x1p-24f);
    float t0 = 0.0f, t1 = tMax;
    auto slab = [&](float lo, float hi, float org, float inv) {
        const float tA = (lo - org) * inv, tB = (hi - org) * inv;
        const float tNearA = tA > tB ? tB : tA;  // the order of the two slab planes
        const float tFarA = (tA > tB ? tA : tB) * kGrow;
        t0 = tNearA > t0 ? tNearA : t0;  // NaN-safe: NaN compares false and leaves t0
        t1 = tFarA < t1 ? tFarA : t1;
    };
    slab(b.lo.x, b.hi.x, o.x, invDir.x);
    slab(b.lo.y, b.hi.y, o.y, invDir.y);
    slab(b.lo.z, b.hi.z, o.z, invDir.z);
    tNear = t0;
    return !(t0 > t1);
}

template <class HitPrim>
bool BVH::traverse(Ray& ray, bool anyHit, HitPrim&& hitPrim) const {
    if (nodes_.empty()) return false;
    const Vec3 invDir(1.0f / ray.d.x, 1.0f / ray.d.y, 1.0f / ray.d.z);
    const bool dirNeg[3] = {ray.d.x < 0.0f, ray.d.y < 0.0f, ray.d.z < 0.0f};
    uint32_t stack[kMaxDepth + 1];
    int top = 0;
    uint32_t node = 0;
    bool hit = false;
    float tNear;
    if (!intersectBox(nodes_[0].box, ray.o, invDir, ray.tMax, tNear)) return false;
    for (;;) {
        const BVHNode& n = nodes_[node];
        if (n.count > 0) {
            for (uint32_t i = n.first; i < n.first + n.count; ++i) {
                if (hitPrim(primIndex_[i], ray)) {
                    hit = true;
                    if (anyHit) return true;
                }
            }
        } else {
            // Near child first: the one on the side the ray comes from along the split axis.
            uint32_t nearC = n.first, farC = n.first + 1;
            if (dirNeg[n.axis]) std::swap(nearC, farC);
            float tN, tF;
            bool hN = intersectBox(nodes_[nearC].box, ray.o, invDir, ray.tMax, tN);
            bool hF = intersectBox(nodes_[farC].box, ray.o, invDir, ray.tMax, tF);
            if (hN && hF) {
                stack[top++] = farC;
                node = nearC;
                continue;
            }
            if (hN) {
                node = nearC;
                continue;
            }
            if (hF) {
                node = farC;
                continue;
            }
        }
        // Pop, skipping nodes the (shortened) ray no longer reaches.
        for (;;) {
            if (top == 0) return hit;
            node = stack[--top];
            if (intersectBox(nodes_[node].box, ray.o, invDir, ray.tMax, tNear)) break;
        }
    }
}

}  // namespace ps
