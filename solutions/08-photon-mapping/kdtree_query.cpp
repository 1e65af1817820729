// Lesson 8 — searching the photon map: the k nearest photons with a bounded max-heap, and every
// photon within a radius. Interface: lessons/08-photon-mapping/photonmap.h. Equation numbers
// refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

//! BEGIN
namespace {

struct KnnSearch {
    const PhotonMap& map;
    Vec3 x;
    size_t k;
    float bound;  // maxD2 until k photons are found, then the farthest one's d2
    std::vector<NearPhoton>& found;
    int visited = 0;

    void locate(size_t i) {
        const Photon& ph = map.nodes[i];
        const size_t left = 2 * i, n = map.size();
        if (left <= n) {
            const float delta = x[ph.axis] - ph.p[ph.axis];
            const size_t nearChild = delta > 0.0f ? left + 1 : left, farChild = delta > 0.0f ? left : left + 1;
            if (nearChild <= n) locate(nearChild);
            if (farChild <= n && delta * delta <= bound) locate(farChild);
        }
        ++visited;
        const float d2 = photonDistance2(ph.p, x);
        if (d2 > bound) return;
        if (found.size() < k) {
            found.push_back({uint32_t(i), d2});
            std::push_heap(found.begin(), found.end(), nearerPhoton);
            if (found.size() == k) bound = found[0].d2;
        } else {
            std::pop_heap(found.begin(), found.end(), nearerPhoton);
            found.back() = {uint32_t(i), d2};
            std::push_heap(found.begin(), found.end(), nearerPhoton);
            bound = found[0].d2;
        }
    }
};

struct RadiusSearch {
    const PhotonMap& map;
    Vec3 x;
    float r2;
    std::vector<NearPhoton>& found;
    int visited = 0;

    void locate(size_t i) {
        const Photon& ph = map.nodes[i];
        const size_t left = 2 * i, n = map.size();
        if (left <= n) {
            const float delta = x[ph.axis] - ph.p[ph.axis];
            const size_t sameSide = delta > 0.0f ? left + 1 : left, otherSide = delta > 0.0f ? left : left + 1;
            if (sameSide <= n) locate(sameSide);
            if (otherSide <= n && delta * delta <= r2) locate(otherSide);
        }
        ++visited;
        const float d2 = photonDistance2(ph.p, x);
        if (d2 <= r2) found.push_back({uint32_t(i), d2});
    }
};

}  // namespace
//! END

int nearestPhotons(const PhotonMap& map, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    //! TODO(08) Eq. 8.5: clear found; nothing to do for an empty map or k <= 0. From the root
    //!          (node 1), recursively at node i with photon ph: if it has children (2i <= size()),
    //!          delta = x[ph.axis] - ph.p[ph.axis]; search the child on x's side first (delta > 0:
    //!          2i + 1, else 2i), then the other one only if delta^2 <= the bound (a child index
    //!          > size() does not exist). Then ph itself: count it as visited, d2 =
    //!          photonDistance2(ph.p, x); if d2 <= bound, keep it: fewer than k found: push_heap;
    //!          else replace the farthest (pop_heap, overwrite back(), push_heap), both with
    //!          nearerPhoton. The bound starts at maxD2 and becomes found[0].d2 once k are found.
    //!          Return the number of photons visited.
    //! STUB (void)map; (void)x; (void)k; (void)maxD2;
    //! STUB found.clear();
    //! STUB return PS_TODO("lesson 08: nearestPhotons", 0);
    //! BEGIN
    found.clear();
    if (map.size() == 0 || k <= 0) return 0;
    found.reserve(size_t(k));
    KnnSearch s{map, x, size_t(k), maxD2, found};
    s.locate(1);
    return s.visited;
    //! END
}

int photonsInRadius(const PhotonMap& map, const Vec3& x, float r2, std::vector<NearPhoton>& found) {
    //! TODO(08) Eq. 8.5 with a fixed bound: clear found, then as nearestPhotons, keeping every
    //!          photon with d2 <= r2 and visiting the far child only if delta^2 <= r2. Return the
    //!          number of photons visited.
    //! STUB (void)map; (void)x; (void)r2;
    //! STUB found.clear();
    //! STUB return PS_TODO("lesson 08: photonsInRadius", 0);
    //! BEGIN
    found.clear();
    if (map.size() == 0) return 0;
    RadiusSearch s{map, x, r2, found};
    s.locate(1);
    return s.visited;
    //! END
}

}  // namespace ps
