// Lesson 8, graded: the kd-tree (Eq. 8.4) and its searches (Eq. 8.5). Exact checks against
// brute force on 10^4 photons with clusters, a flat layer and exact duplicates: the array is a
// left-balanced tree in heap order holding every photon once, each node splits on its subtree's
// axis of largest extent with the kd property on both sides; the k nearest photons have the
// brute-force distances (ties compared by distance, never by index); the radius search finds
// exactly the photons within the radius; and a search prunes: the mean number of nodes it visits
// stays under a stated bound (a search that never prunes visits all 10^4).
#include <map>
#include "lesson08.h"

using namespace lesson08;

namespace {

// The nodes of the subtree at i, into out.
void subtree(const PhotonMap& map, size_t i, std::vector<size_t>& out) {
    if (i > map.size()) return;
    out.push_back(i);
    subtree(map, 2 * i, out);
    subtree(map, 2 * i + 1, out);
}

bool samePhoton(const Photon& a, const Photon& b) {
    return a.p == b.p && a.power == b.power && a.dir[0] == b.dir[0] && a.dir[1] == b.dir[1];
}

}  // namespace

TEST_CASE("kd-tree: the left-balanced subtree size of n nodes (Eq. 8.4) [1 pt]") {
    // Oracle: in heap order, the nodes 1 .. n of a left-balanced tree; node i is in the root's
    // left subtree iff its binary digits start with "10".
    for (size_t n = 1; n <= 300; ++n) {
        size_t expected = 0;
        for (size_t i = 2; i <= n; ++i) {
            size_t top = i;
            while (top >= 4) top >>= 1;
            expected += top == 2;
        }
        const size_t got = ps::leftSubtreeSize(n);
        CHECK_MESSAGE(got == expected, "leftSubtreeSize("
                                           << n << "): expected " << expected
                                           << " (every level full but the last, packed to the left), got " << got);
        if (got != expected) break;
    }
}

TEST_CASE("kd-tree: every photon once, in heap order, split on the axis of largest extent (Eq. 8.4) [2 pts]") {
    for (int n : {1, 2, 3, 7, 8, 100, 10000}) {
        const std::vector<Photon> photons = hardPhotonSet(ps::testseed::seed(801) + uint64_t(n), n);
        PhotonMap map;
        ps::buildPhotonMap(photons, map);
        REQUIRE_MESSAGE(map.nodes.size() == photons.size() + 1,
                        n << " photons: expected map.nodes to have n + 1 = " << n + 1
                          << " entries (node 0 unused, the tree in nodes 1 .. n), got " << map.nodes.size());
        // Every photon exactly once (a multiset of exact copies).
        auto key = [](const Photon& a, const Photon& b) {
            if (a.p.x != b.p.x) return a.p.x < b.p.x;
            if (a.p.y != b.p.y) return a.p.y < b.p.y;
            return a.p.z < b.p.z;
        };
        std::vector<Photon> in = photons, stored(map.nodes.begin() + 1, map.nodes.end());
        std::sort(in.begin(), in.end(), key);
        std::sort(stored.begin(), stored.end(), key);
        bool same = true;
        for (size_t i = 0; i < in.size() && same; ++i) same = samePhoton(in[i], stored[i]);
        CHECK_MESSAGE(same, n << " photons: nodes 1 .. n must hold every input photon exactly once (position, "
                                 "power, direction copied), they do not: a photon is missing, repeated or altered "
                                 "(a median at the wrong index leaves a hole in the heap-order array)");
        if (!same) continue;
        // The kd property and the axis of largest extent, at every node with children.
        std::string wrong;
        for (size_t i = 1; i <= map.size() && wrong.empty(); ++i) {
            if (2 * i > map.size()) continue;
            const Photon& node = map.nodes[i];
            const int a = map.tree.axis[i];
            std::vector<size_t> all, left, right;
            subtree(map, i, all);
            subtree(map, 2 * i, left);
            subtree(map, 2 * i + 1, right);
            Vec3 lo(1e30f), hi(-1e30f);
            for (size_t j : all) {
                lo = glm::min(lo, map.nodes[j].p);
                hi = glm::max(hi, map.nodes[j].p);
            }
            const Vec3 e = hi - lo;
            const float largest = std::max(e.x, std::max(e.y, e.z));
            std::ostringstream why;
            if (a > 2) why << "node " << i << ": axis " << a << " is not 0, 1 or 2";
            else if (e[a] < largest)
                why << "node " << i << " (" << all.size() << " photons below it): splits on axis " << a << " (extent "
                    << num(e[a]) << "), expected the axis of largest extent (" << num(largest) << ", extents " << str(e)
                    << ")";
            else {
                for (size_t j : left)
                    if (map.nodes[j].p[a] > node.p[a]) {
                        why << "node " << i << " (axis " << a << ", coordinate " << num(node.p[a]) << "): node " << j
                            << " of its left subtree has " << num(map.nodes[j].p[a]) << ", expected <= the node's";
                        break;
                    }
                for (size_t j : right)
                    if (why.str().empty() && map.nodes[j].p[a] < node.p[a]) {
                        why << "node " << i << " (axis " << a << ", coordinate " << num(node.p[a]) << "): node " << j
                            << " of its right subtree has " << num(map.nodes[j].p[a]) << ", expected >= the node's";
                        break;
                    }
            }
            wrong = why.str();
        }
        CHECK_MESSAGE(wrong.empty(), n << " photons: " << wrong);
    }
    PhotonMap empty;
    ps::buildPhotonMap({}, empty);
    CHECK_MESSAGE(empty.size() == 0, "no photons: expected an empty map, got " << empty.size() << " nodes");
}

TEST_CASE("kd-tree: the k nearest photons are the brute-force ones, a max-heap (Eq. 8.5) [3 pts]") {
    const std::vector<Photon> photons = hardPhotonSet(ps::testseed::seed(802));
    PhotonMap map;
    ps::buildPhotonMap(photons, map);
    REQUIRE(map.size() == photons.size());
    ps::Rng rng(ps::testseed::seed(803));
    std::vector<ps::NearPhoton> found;
    int failures = 0;
    for (int q = 0; q < 400 && failures == 0; ++q) {
        // Query points: at a photon (often a duplicate), in a cluster, on the layer, anywhere.
        Vec3 x = q % 4 == 0   ? map.nodes[1 + size_t(rng.uniform() * float(map.size())) % map.size()].p
                 : q % 4 == 1 ? Vec3(0.2f, 0.2f, 0.2f) + 0.02f * (uniform3(rng) - 0.5f)
                 : q % 4 == 2 ? onLayer(rng)
                              : 1.2f * uniform3(rng) - 0.1f;
        const int ks[5] = {1, 8, 50, 200, 500};
        const int k = ks[q % 5];
        const float maxD2 = q % 3 == 0 ? 0.01f : 1e30f;
        const int visited = ps::nearestPhotons(map, x, k, maxD2, found);
        std::vector<float> d = allDistances(map, x), within;
        for (float v : d)
            if (v <= maxD2) within.push_back(v);
        std::sort(within.begin(), within.end());
        within.resize(std::min(within.size(), size_t(k)));
        std::vector<float> got;
        std::ostringstream why;
        for (const ps::NearPhoton& f : found) {
            if (f.node < 1 || f.node > map.size()) {
                why << "a node index " << f.node << " outside 1 .. " << map.size();
                break;
            }
            if (f.d2 != ps::photonDistance2(map.nodes[f.node].p, x)) {
                why << "node " << f.node << " with d2 = " << num(f.d2)
                    << ", but its photon is at d2 = " << num(ps::photonDistance2(map.nodes[f.node].p, x));
                break;
            }
            got.push_back(f.d2);
        }
        std::vector<uint32_t> nodes;
        for (const ps::NearPhoton& f : found) nodes.push_back(f.node);
        std::sort(nodes.begin(), nodes.end());
        if (why.str().empty() && std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end())
            why << "a node found twice";
        std::sort(got.begin(), got.end());
        if (why.str().empty() && got != within) {
            why << "expected " << within.size() << " photons with the brute-force squared distances";
            if (!within.empty()) why << " " << num(within.front()) << " .. " << num(within.back());
            why << ", got " << got.size();
            if (!got.empty()) why << " with " << num(got.front()) << " .. " << num(got.back());
            size_t i = 0;
            while (i < got.size() && i < within.size() && got[i] == within[i]) ++i;
            if (i < within.size())
                why << " (the " << i + 1 << "-th nearest, d2 = " << num(within[i]) << ", missing or wrong"
                    << " : a subtree pruned that could hold a nearer photon?)";
        }
        if (why.str().empty() && !std::is_heap(found.begin(), found.end(), ps::nearerPhoton))
            why << "found is not a max-heap under nearerPhoton (found[0] must be the farthest)";
        if (why.str().empty() && visited < int(found.size()))
            why << "returned " << visited << " visited nodes, fewer than the " << found.size() << " found";
        if (!why.str().empty()) {
            ++failures;
            FAIL_CHECK("nearestPhotons(x = " << str(x) << ", k = " << k << ", maxD2 = " << num(maxD2)
                                             << ") on 10^4 photons (clusters, a layer, duplicates): " << why.str());
        }
    }
    // Small maps and an empty one.
    PhotonMap small;
    ps::buildPhotonMap(hardPhotonSet(ps::testseed::seed(804), 3), small);
    CHECK_MESSAGE((ps::nearestPhotons(small, Vec3(0.5f), 10, 1e30f, found), found.size() == 3),
                  "3 photons, k = 10: expected all 3, got " << found.size());
    PhotonMap empty;
    found.assign(4, ps::NearPhoton{});
    ps::nearestPhotons(empty, Vec3(0.0f), 5, 1.0f, found);
    CHECK_MESSAGE(found.empty(), "an empty map: expected nothing found (and found cleared), got " << found.size());
}

TEST_CASE(
    "kd-tree: the radius search finds exactly the photons within the radius, and its visitor may lower it (Eq. 8.5) [2 pts]") {
    const std::vector<Photon> photons = hardPhotonSet(ps::testseed::seed(805));
    PhotonMap map;
    ps::buildPhotonMap(photons, map);
    REQUIRE(map.size() == photons.size());
    ps::Rng rng(ps::testseed::seed(806));
    std::vector<ps::NearPhoton> found;
    for (int q = 0; q < 300; ++q) {
        const Vec3 x = q % 3 == 0   ? map.nodes[1 + size_t(rng.uniform() * float(map.size())) % map.size()].p
                       : q % 3 == 1 ? Vec3(0.04f * float(q % 25), 0.5f, 0.3f + 0.02f * float(q % 5))  // duplicates
                                    : uniform3(rng);
        const float radii2[5] = {0.0f, 1e-4f, 1e-3f, 0.01f, 0.05f};
        const float r2 = radii2[q % 5];
        ps::photonsInRadius(map, x, r2, found);
        std::vector<uint32_t> expected, got;
        for (size_t i = 1; i <= map.size(); ++i)
            if (ps::photonDistance2(map.nodes[i].p, x) <= r2) expected.push_back(uint32_t(i));
        for (const ps::NearPhoton& f : found) got.push_back(f.node);
        std::sort(got.begin(), got.end());
        if (got != expected) {
            FAIL_CHECK("photonsInRadius(x = " << str(x) << ", r2 = " << num(r2) << ") on 10^4 photons: expected the "
                                              << expected.size()
                                              << " photons with d2 <= r2 (brute force, each once), got " << got.size()
                                              << (got.size() < expected.size() ? " (pruned too much?)" : ""));
            break;
        }
    }
    // The visitor may lower the bound (the k-nearest search does): one that lowers it to every d2
    // it is handed must be handed ever nearer points and end at the nearest within r2 (brute force).
    for (int q = 0; q < 100; ++q) {
        const Vec3 x =
            q % 2 == 0 ? map.nodes[1 + size_t(rng.uniform() * float(map.size())) % map.size()].p : uniform3(rng);
        const float r2 = q % 4 < 2 ? 0.01f : 1e30f;
        float last = r2, nearest = r2;
        int handed = 0, farther = 0;
        bool any = false;
        ps::pointsInRadius(map.tree, x, r2, [&](uint32_t, float d2, float& bound) {
            ++handed;
            if (d2 > last) ++farther;
            last = d2;
            bound = d2;
        });
        for (size_t i = 1; i <= map.size(); ++i) {
            const float d2 = ps::photonDistance2(map.nodes[i].p, x);
            if (d2 <= nearest) {
                nearest = d2;
                any = true;
            }
        }
        std::ostringstream why;
        if (farther > 0)
            why << farther << " of the " << handed
                << " points handed to visit were farther than the bound visit had lowered it to before"
                << " (compare with the bound as it is now)";
        else if (!any && handed > 0) why << "no point lies within r2, but " << handed << " were handed to visit";
        else if (any && (handed == 0 || last != nearest))
            why << "the nearest point within r2 is at d2 = " << num(nearest) << ", the last one handed to visit at "
                << (handed == 0 ? std::string("(none)") : num(last)) << " (a subtree pruned that could hold it?)";
        if (!why.str().empty()) {
            FAIL_CHECK("pointsInRadius(x = " << str(x) << ", r2 = " << num(r2)
                                             << ") with a visitor that lowers the bound to each d2 it is handed: "
                                             << why.str());
            break;
        }
    }
}

TEST_CASE("kd-tree: a search prunes, visiting far fewer nodes than a full scan (Eq. 8.5) [2 pts]") {
    // Uniform photons in the unit cube, queries inside it. A kd-tree search that prunes by the
    // distance to the splitting plane visits a few hundred nodes for k = 50 (the reference: ~300
    // on average); the stated bound is 1500 (15 % of the photons), and 400 for a radius holding
    // ~20 photons. A search that never prunes visits all 10^4.
    ps::Rng rng(ps::testseed::seed(807));
    std::vector<Photon> photons;
    for (int i = 0; i < 10000; ++i) photons.push_back(photonAt(uniform3(rng)));
    PhotonMap map;
    ps::buildPhotonMap(photons, map);
    REQUIRE(map.size() == photons.size());
    std::vector<ps::NearPhoton> found;
    double knn = 0.0, radius = 0.0;
    const int queries = 200;
    for (int q = 0; q < queries; ++q) {
        const Vec3 x = 0.1f + 0.8f * uniform3(rng);
        knn += ps::nearestPhotons(map, x, 50, 1e30f, found);
        radius += ps::photonsInRadius(map, x, 0.0078f, found);  // (4/3) pi r^3 * 10^4 ~ 20 photons
    }
    knn /= queries;
    radius /= queries;
    MESSAGE("visited nodes on average: k = 50: " << num(knn) << ", radius: " << num(radius));
    CHECK_MESSAGE(knn <= 1500.0,
                  "k = 50 nearest of 10^4 uniform photons: expected at most 1500 visited nodes on average, "
                  "got "
                      << num(knn)
                      << " (visit the far child only if the squared distance to the splitting plane is "
                         "<= the current bound, which shrinks to found[0].d2 once k are found)");
    CHECK_MESSAGE(knn >= 50.0, "k = 50: a search must visit at least the 50 photons it returns, it says it visited "
                                   << num(knn) << " on average (return the number of nodes visited)");
    CHECK_MESSAGE(radius <= 400.0,
                  "radius search (about 20 photons within r) on 10^4 uniform photons: expected at most "
                  "400 visited nodes on average, got "
                      << num(radius) << " (visit the far child only if delta^2 <= r2)");
}
