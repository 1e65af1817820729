// Lesson 8 — the photon map's kd-tree: left-balanced, in one array in heap order. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include <tuple>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

size_t leftSubtreeSize(size_t n) {
    //! TODO(08) Eq. 8.4: a left-balanced tree of n nodes has h = floor(log2 n) full levels above
    //!          its last one (root at level 0), which holds n - (2^h - 1) nodes packed to the left.
    //!          The left subtree has the 2^(h-1) - 1 nodes of its full levels plus
    //!          min(n - (2^h - 1), 2^(h-1)) of the last level's. n == 1: 0.
    //! STUB (void)n;
    //! STUB return PS_TODO("lesson 08: leftSubtreeSize", size_t(0));
    //! BEGIN
    if (n <= 1) return 0;
    size_t full = 1;  // 2^h
    while (full * 2 <= n) full *= 2;
    const size_t half = full / 2;  // 2^(h-1)
    const size_t last = n - (full - 1);
    return (half - 1) + std::min(last, half);
    //! END
}

//! BEGIN
namespace {

// Puts the left-balanced kd-tree of photons[begin, end) at node `node` of out (Eq. 8.4).
void balance(std::vector<Photon>& photons, size_t begin, size_t end, size_t node, std::vector<Photon>& out) {
    const size_t n = end - begin;
    if (n == 0) return;
    if (n == 1) {
        out[node] = photons[begin];
        out[node].axis = 0;
        return;
    }
    Vec3 lo = photons[begin].p, hi = lo;
    for (size_t i = begin + 1; i < end; ++i) {
        lo = glm::min(lo, photons[i].p);
        hi = glm::max(hi, photons[i].p);
    }
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t median = begin + leftSubtreeSize(n);
    // By the axis's coordinate; ties (photons on an axis-aligned wall) broken by everything else
    // the photon holds: std::nth_element leaves equal photons in an order of the standard
    // library's choosing, so without a total order the tree, and every image made with it,
    // would differ between libstdc++ and libc++.
    const auto key = [axis](const Photon& a) {
        return std::make_tuple(a.p[axis], a.p[(axis + 1) % 3], a.p[(axis + 2) % 3], a.power.r, a.power.g, a.power.b,
                               a.dir[0], a.dir[1]);
    };
    std::nth_element(photons.begin() + long(begin), photons.begin() + long(median), photons.begin() + long(end),
                     [&key](const Photon& a, const Photon& b) { return key(a) < key(b); });
    out[node] = photons[median];
    out[node].axis = static_cast<uint8_t>(axis);
    balance(photons, begin, median, 2 * node, out);
    balance(photons, median + 1, end, 2 * node + 1, out);
}

}  // namespace
//! END

void buildPhotonMap(std::vector<Photon> photons, PhotonMap& map) {
    //! TODO(08) Eq. 8.4: map.nodes gets n + 1 entries (node 0 unused), then the tree of all photons
    //!          at node 1, recursively, for the photons of a node in one range [begin, end) of the
    //!          array: the axis of largest extent of their bounding box; the median index
    //!          m = begin + leftSubtreeSize(end - begin), found with std::nth_element on that
    //!          coordinate (O(n) per level, O(n log n) in all; do not sort); the median photon goes
    //!          to the node with its axis, [begin, m) to node 2i, (m, end) to node 2i + 1. A node
    //!          without children keeps axis 0. No photons: map.nodes empty.
    //! STUB (void)photons; (void)map;
    //! STUB (void)PS_TODO("lesson 08: buildPhotonMap", 0);
    //! BEGIN
    map.nodes.clear();
    if (photons.empty()) return;
    map.nodes.resize(photons.size() + 1);
    balance(photons, 0, photons.size(), 1, map.nodes);
    //! END
}

}  // namespace ps
