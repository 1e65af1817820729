// Lesson 12, graded: the spatial tree (Eq. 12.10, 12.11) and the field's statistics: a point's
// cell against the leaf whose box contains it (the boxes computed by the test's own recursion),
// the cuts at the stated number of records, and every cell's sums against brute force over the
// records whose points lie in its box.
#include "lesson12.h"

using namespace lesson12;

namespace {

// Every leaf's box, by the test's own recursion over the nodes (a node halves its box along its
// axis; the lower half is child 0).
struct LeafBox {
    ps::AABB box;
    uint32_t cell;
};
void boxesOf(const ps::SpatialTree& t, uint32_t node, const ps::AABB& box, std::vector<LeafBox>& out) {
    const ps::SpatialNode& n = t.nodes[node];
    if (n.isLeaf()) {
        out.push_back({box, n.cell});
        return;
    }
    const float mid = 0.5f * (box.lo[n.axis] + box.hi[n.axis]);
    ps::AABB lo = box, hi = box;
    lo.hi[n.axis] = mid;
    hi.lo[n.axis] = mid;
    boxesOf(t, n.child[0], lo, out);
    boxesOf(t, n.child[1], hi, out);
}
// The leaf whose box holds p, boxes half-open ([lo, hi) on every axis, the root's far faces and
// anything outside clamped in).
uint32_t bruteCell(const std::vector<LeafBox>& leaves, const ps::AABB& root, Vec3 p) {
    for (int a = 0; a < 3; ++a) p[a] = std::min(std::max(p[a], root.lo[a]), std::nextafter(root.hi[a], root.lo[a]));
    for (const LeafBox& l : leaves) {
        bool in = true;
        for (int a = 0; a < 3; ++a) in = in && p[a] >= l.box.lo[a] && p[a] < l.box.hi[a];
        if (in) return l.cell;
    }
    return ~0u;
}

// A hand-made tree over [0, 8] x [0, 4] x [0, 2]: the root cut in x; its upper half in y; that
// one's lower half in z (depth 3); 5 leaves, cells in an order unrelated to the nodes'.
ps::SpatialTree handSpatialTree() {
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(8.0f, 4.0f, 2.0f);
    ps::SpatialTree t(box);
    t.nodes.resize(7);
    t.nodes[0].axis = 0, t.nodes[0].child[0] = 1, t.nodes[0].child[1] = 2;
    t.nodes[1].axis = 1, t.nodes[1].cell = 3;
    t.nodes[2].axis = 1, t.nodes[2].child[0] = 3, t.nodes[2].child[1] = 4;
    t.nodes[3].axis = 2, t.nodes[3].child[0] = 5, t.nodes[3].child[1] = 6;
    t.nodes[4].axis = 2, t.nodes[4].cell = 0;
    t.nodes[5].axis = 0, t.nodes[5].cell = 2;
    t.nodes[6].axis = 0, t.nodes[6].cell = 1;
    return t;
}

}  // namespace

TEST_CASE("spatial tree: a point's cell is the leaf whose box contains it (Eq. 12.10) [1 pt]") {
    const ps::SpatialTree t = handSpatialTree();
    std::vector<LeafBox> leaves;
    boxesOf(t, 0, t.bounds(), leaves);
    std::vector<Vec3> points = {Vec3(4.0f, 1.0f, 1.0f),   Vec3(3.999f, 2.0f, 1.0f), Vec3(5.0f, 2.0f, 1.0f),
                                Vec3(5.0f, 1.999f, 0.5f), Vec3(5.0f, 1.0f, 0.5f),   Vec3(5.0f, 1.0f, 1.5f),
                                Vec3(8.0f, 4.0f, 2.0f),   Vec3(-1.0f, 9.0f, -3.0f), Vec3(7.9f, 0.1f, 1.0f)};
    ps::Rng rng(ps::testseed::seed(1204), 1);
    for (int k = 0; k < 500; ++k) points.push_back(Vec3(8.0f, 4.0f, 2.0f) * uniform3(rng));
    int wrong = 0;
    std::string first;
    for (const Vec3& p : points) {
        const uint32_t want = bruteCell(leaves, t.bounds(), p), got = t.cellOf(p);
        if (got != want && wrong++ == 0)
            first = "point " + str(p) + ": expected cell " + std::to_string(want) + ", got " + std::to_string(got);
    }
    CHECK_MESSAGE(wrong == 0,
                  "SpatialTree::cellOf on a hand-made tree over [(0, 0, 0), (8, 4, 2)] (5 leaves, depth 3): "
                      << wrong << " of " << points.size()
                      << " points in the wrong cell (a node's upper half starts at its box's middle, "
                         "inclusive); the first: "
                      << first);
}

TEST_CASE("spatial tree: a leaf is cut when its cell has more than the stated number of records (Eq. 12.11) [1 pt]") {
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(1.0f);
    constexpr uint32_t T = 100;
    struct Case {
        uint32_t samples;
        size_t maxCells, cells;
        const char* what;
    };
    for (const Case& c : {Case{T, 64, 1, "exactly the threshold: not cut"}, Case{T + 1, 64, 2, "one more: cut once"},
                          Case{4 * T + 3, 64, 4, "4 T + 3: cut, and both halves (2 T + 1) cut again"},
                          Case{4 * T, 64, 4, "4 T: the halves (2 T) cut again, theirs (T) not"},
                          Case{100 * T, 3, 3, "many records but at most 3 cells"}}) {
        ps::SpatialTree t(box);
        std::vector<ps::GuideCell> cells(1);
        cells[0].samples = c.samples;
        cells[0].side[2].learning.record(Vec3(0.0f, 0.0f, 1.0f), 2.5f);
        t.subdivide(cells, T, c.maxCells);
        const size_t want = c.cells;
        CHECK_MESSAGE(cells.size() == want, "SpatialTree::subdivide(threshold "
                                                << T << ", maxCells " << c.maxCells << ") of one leaf with "
                                                << c.samples << " records: expected " << want << " cells, got "
                                                << cells.size());
        if (cells.size() != want) continue;
        std::vector<LeafBox> leaves;
        boxesOf(t, 0, t.bounds(), leaves);
        CHECK_MESSAGE(leaves.size() == cells.size(), "SpatialTree::subdivide: expected one leaf per cell, got "
                                                         << leaves.size() << " leaves for " << cells.size()
                                                         << " cells");
        // Axes: every node's children cut the next axis; the leaves' cells are all different.
        bool axes = true;
        for (const ps::SpatialNode& n : t.nodes)
            if (!n.isLeaf())
                for (const uint32_t k : n.child) axes = axes && t.nodes[k].axis == (n.axis + 1) % 3;
        CHECK_MESSAGE(axes,
                      "SpatialTree::subdivide: the children of a node cutting axis a must cut axis (a + 1) mod 3");
        std::vector<int> seen(cells.size(), 0);
        for (const LeafBox& l : leaves) seen[l.cell]++;
        bool once = true;
        for (const int s : seen) once = once && s == 1;
        CHECK_MESSAGE(once, "SpatialTree::subdivide: every cell must belong to exactly one leaf");
        uint32_t remaining = c.samples;
        int levels = 0;
        while (remaining > T && (size_t(1) << (levels + 1)) <= c.maxCells && c.samples != 100 * T) {
            remaining /= 2;
            ++levels;
        }
        for (size_t k = 0; k < cells.size(); ++k) {
            CHECK_MESSAGE(cells[k].side[2].learning.total() == 2.5f,
                          "SpatialTree::subdivide: cell " << k << " must be a copy of the cut one (its trees), got "
                                                          << num(cells[k].side[2].learning.total()) << " as a total");
            if (c.samples != 100 * T)
                CHECK_MESSAGE(cells[k].samples == remaining,
                              "SpatialTree::subdivide(" << c.what << "): cell " << k << " expected " << remaining
                                                        << " records (halved at every cut), got " << cells[k].samples);
        }
    }
}

TEST_CASE("learned field: a cell's statistics are the sums of what was recorded in it (brute force) [1 pt]") {
    ps::AABB box;
    box.lo = Vec3(-1.0f, 0.0f, 2.0f);
    box.hi = Vec3(3.0f, 2.0f, 4.0f);
    ps::GuideSettings settings;
    settings.spatialThreshold = 40;
    ps::GuideField field(box, settings);
    ps::Rng rng(ps::testseed::seed(1205), 2);
    // Two passes: the first cuts the tree where its records are many (near the corner lo), the
    // second's records are checked cell by cell.
    struct Point {
        Vec3 p, w;
        float value;
        int side;
    };
    const auto draw = [&](int n) {
        std::vector<Point> pts;
        for (int k = 0; k < n; ++k) {
            const float s = k % 3 ? 0.3f : 1.0f;  // two thirds of them near the lower corner
            const Vec3 p = box.lo + s * box.extent() * uniform3(rng);
            pts.push_back({p, ps::sampleUniformSphere(rng.uniform2()), 0.5f + rng.uniform(), k % 6});
        }
        return pts;
    };
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<Point> pts = draw(3000);
        std::vector<ps::RadianceRecord> recs;
        for (const Point& q : pts) recs.push_back({int(field.cellOf(q.p)), q.side, q.w, q.value});
        field.add(recs);
        if (pass == 1) {
            std::vector<LeafBox> leaves;
            boxesOf(field.spatialTree(), 0, field.spatialTree().bounds(), leaves);
            CHECK_MESSAGE(leaves.size() > 4,
                          "GuideField after a pass of 3000 records, threshold 40 sqrt(2^0): expected "
                          "the spatial tree cut where the records were, got "
                              << leaves.size() << " leaves");
            int wrong = 0;
            std::string first;
            for (const LeafBox& l : leaves)
                for (int side = 0; side < 6; ++side) {
                    double sum = 0.0;
                    uint32_t n = 0;
                    for (const Point& q : pts)
                        if (q.side == side && bruteCell(leaves, field.spatialTree().bounds(), q.p) == l.cell) {
                            sum += q.value;
                            ++n;
                        }
                    const ps::GuideSide& c = field.cell(l.cell).side[side];
                    if ((c.samples != n || std::abs(c.learning.total() - sum) > 1e-4 * (1.0 + sum)) && wrong++ == 0)
                        first = "cell " + std::to_string(l.cell) + " (box " + str(l.box.lo) + " - " + str(l.box.hi) +
                                "), side " + std::to_string(side) + ": expected " + std::to_string(n) +
                                " records of total " + num(sum) + ", got " + std::to_string(c.samples) + " of total " +
                                num(c.learning.total());
                }
            CHECK_MESSAGE(wrong == 0, "GuideField: " << wrong << " of " << leaves.size()
                                                     << " cells do not hold the records whose points lie in their box; "
                                                        "the first, "
                                                     << first);
        }
        field.endPass(pass);
    }
}
