// Lesson 12, graded: the directional distribution (Eq. 12.5-12.9), on hand-made quadtrees whose
// every leaf is known: the density against each leaf's energy share over its area, its integral
// over the sphere on a grid of directions fine enough to be exact for leaves down to depth 10,
// sampling against the leaves' energies (chi-square in the square), recording against brute-force
// sums, and refinement against the energy of every square of the old tree.
#include "lesson12.h"
#include "warps.h"

using namespace lesson12;

TEST_CASE(
    "directional distribution: the density of every leaf, per unit solid angle, integrates to 1 (Eq. 12.5, 12.6) [2 pts]") {
    const ps::DirectionalTree t = handTree();
    const std::vector<Leaf> leaves = leavesOf(t);
    const double total = totalOf(leaves);
    int wrong = 0;
    std::string first;
    for (const Leaf& l : leaves)
        for (const double a : {0.25, 0.75})
            for (const double b : {0.3, 0.7}) {
                const double u = l.square.x + a * l.square.size, v = l.square.y + b * l.square.size;
                const double want = l.energy / total / (l.square.size * l.square.size) / (4.0 * kPiD);
                const double got = t.pdf(directionOf(u, v));
                if (std::abs(got - want) > 1e-5 * want + 1e-9 && wrong++ == 0)
                    first = "in the leaf at depth " + std::to_string(l.depth) + " with corner (" + num(l.square.x) +
                            ", " + num(l.square.y) + ") of the square, energy " + num(l.energy) + " of " + num(total) +
                            ": expected " + num(want) + " per steradian, got " + num(got) +
                            (std::abs(got - want * 4.0 * kPiD) < 1e-4 * want * 4.0 * kPiD
                                 ? " (that is the density per unit area of the square: Eq. 12.5)"
                                 : "");
            }
    CHECK_MESSAGE(wrong == 0, "DirectionalTree::pdf on a hand-made tree of 13 leaves down to depth 4: "
                                  << wrong << " of " << 4 * leaves.size() << " directions wrong; the first " << first);
    // The integral over the sphere: a 1024 x 1024 grid of (cos theta, phi), equal areas, the
    // midpoint of every cell (exact for leaves down to depth 10).
    constexpr int N = 1024;
    double integral = 0.0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) integral += t.pdf(directionOf((i + 0.5) / N, (j + 0.5) / N));
    integral *= 4.0 * kPiD / (double(N) * N);
    CHECK_MESSAGE(std::abs(integral - 1.0) < 1e-4,
                  "DirectionalTree::pdf of the hand-made tree: the integral over the "
                  "sphere (per steradian, 1024^2 equal cells) expected 1, got "
                      << num(integral));
    const ps::DirectionalTree empty;
    const double u = empty.pdf(Vec3(0.0f, 0.6f, 0.8f));
    CHECK_MESSAGE(std::abs(u - 1.0 / (4.0 * kPiD)) < 1e-7,
                  "DirectionalTree::pdf of a tree without energy: expected the uniform density 1 / (4 pi) = "
                      << num(1.0 / (4.0 * kPiD)) << ", got " << num(u));
}

TEST_CASE("directional distribution: sampling follows the energies (chi-square, Eq. 12.7) [2 pts]") {
    ps::DirectionalTree t = handTree();
    // One narrow leaf deeper down: node 4's quadrant 3 cut three more levels (depth 7), where a
    // float that is rescaled level after level has lost its bits.
    uint32_t parent = 4;
    for (int level = 0; level < 3; ++level) {
        const uint32_t child = uint32_t(t.nodes.size());
        t.nodes.emplace_back();
        const float e = t.nodes[parent].energy[3];
        t.nodes[child].energy[0] = 0.0625f * e, t.nodes[child].energy[1] = 0.0625f * e;
        t.nodes[child].energy[2] = 0.125f * e, t.nodes[child].energy[3] = 0.75f * e;
        t.nodes[parent].child[3] = child;
        parent = child;
    }
    const std::vector<Leaf> leaves = leavesOf(t);
    const double total = totalOf(leaves);
    // Bins: a 32 x 32 grid of the square, and every leaf smaller than a bin a bin of its own.
    constexpr int B = 32;
    std::vector<Square> bins;
    for (int i = 0; i < B; ++i)
        for (int j = 0; j < B; ++j) bins.push_back({double(i) / B, double(j) / B, 1.0 / B});
    const size_t grid = bins.size();
    for (const Leaf& l : leaves)
        if (l.square.size < 1.0 / B) bins.push_back(l.square);
    std::vector<double> expected(bins.size(), 0.0), observed(bins.size(), 0.0);
    for (size_t b = 0; b < bins.size(); ++b) expected[b] = energyIn(leaves, bins[b]);
    // A grid bin holding small leaves: what they hold is counted in their own bins.
    for (size_t b = grid; b < bins.size(); ++b)
        for (size_t g = 0; g < grid; ++g)
            if (bins[g].contains(bins[b].x, bins[b].y)) expected[g] -= expected[b];
    constexpr int samples = 200000;
    for (double& e : expected) e *= samples / total;
    ps::Rng rng(ps::testseed::seed(1201), 3);
    int outside = 0;
    for (int s = 0; s < samples; ++s) {
        const Vec3 w = t.sample(rng.uniform2());
        if (!(std::abs(glm::length(w) - 1.0f) < 1e-3f)) {
            ++outside;
            continue;
        }
        double u, v;
        squareOf(w, u, v);
        size_t bin = size_t(std::min(B - 1, int(u * B))) * B + size_t(std::min(B - 1, int(v * B)));
        for (size_t b = grid; b < bins.size(); ++b)
            if (bins[b].contains(u, v)) bin = b;
        observed[bin] += 1.0;
    }
    CHECK_MESSAGE(outside == 0,
                  "DirectionalTree::sample: " << outside << " of " << samples << " samples were not unit directions");
    const ps::stats::ChiSquareResult r = ps::stats::chiSquare(observed, expected, alpha());
    CHECK_MESSAGE(r.passed, "DirectionalTree::sample on a hand-made tree of 16 leaves down to depth 7, "
                                << samples
                                << " samples binned in the square (32 x 32, and every leaf smaller than a "
                                   "bin on its own) against the leaves' energies: "
                                << r.report);
    const ps::DirectionalTree empty;
    for (const Vec2& u : {Vec2(0.1f, 0.2f), Vec2(0.6f, 0.9f), Vec2(0.95f, 0.05f)}) {
        const Vec3 got = empty.sample(u), want = ps::sampleUniformSphere(u);
        CHECK_MESSAGE(glm::length(got - want) < 1e-5f, "DirectionalTree::sample("
                                                           << str(u)
                                                           << ") of a tree without energy: expected the uniform "
                                                              "sphere's direction "
                                                           << str(want) << ", got " << str(got));
    }
}

TEST_CASE("directional distribution: a record adds its value to every quadrant on its way down (Eq. 12.8) [1 pt]") {
    ps::DirectionalTree t = handTree();
    t.clear();
    const std::vector<Leaf> leaves = leavesOf(t);
    ps::Rng rng(ps::testseed::seed(1203), 5);
    struct Rec {
        double u, v, value;
    };
    std::vector<Rec> recs;
    for (int k = 0; k < 400; ++k) {
        // Half of them in root quadrant 0, where the tree is deep.
        const double u = k % 2 ? 0.5 * rng.uniform() : rng.uniform(), v = k % 2 ? 0.5 * rng.uniform() : rng.uniform();
        const double value = 0.25 * (1 + k % 7);
        const Vec3 w = directionOf(u, v);
        double uu, vv;
        squareOf(w, uu, vv);  // the point as the float direction has it
        recs.push_back({uu, vv, value});
        t.record(w, float(value));
    }
    // Every quadrant of every node against the sum of the values whose point is in its square.
    int wrong = 0;
    std::string first;
    std::function<void(uint32_t, const Square&, int)> check = [&](uint32_t node, const Square& sq, int depth) {
        for (int i = 0; i < 4; ++i) {
            const Square q = sq.quadrant(i);
            double want = 0.0;
            for (const Rec& r : recs)
                if (q.contains(r.u, r.v)) want += r.value;
            const double got = t.nodes[node].energy[i];
            if (std::abs(got - want) > 1e-4 * (1.0 + want) && wrong++ == 0)
                first = "node " + std::to_string(node) + " (depth " + std::to_string(depth) + "), quadrant " +
                        std::to_string(i) + ": expected " + num(want) + ", got " + num(got);
            if (t.nodes[node].child[i] != 0) check(t.nodes[node].child[i], q, depth + 1);
        }
    };
    check(0, Square(), 0);
    (void)leaves;
    CHECK_MESSAGE(wrong == 0, "DirectionalTree::record: 400 records into a hand-made tree of 5 nodes: "
                                  << wrong
                                  << " quadrants do not hold the sum of the values recorded in them; the first, "
                                  << first);
}

TEST_CASE("directional distribution: refinement keeps the total and cuts where the energy is (Eq. 12.9) [2 pts]") {
    const ps::DirectionalTree t = handTree();
    const std::vector<Leaf> before = leavesOf(t);
    const double total = totalOf(before);
    struct Case {
        float rho;
        int maxDepth;
    };
    for (const Case c : {Case{0.01f, 16}, Case{0.05f, 16}, Case{0.2f, 16}, Case{0.01f, 3}}) {
        const ps::DirectionalTree r = t.refined(c.rho, c.maxDepth);
        const std::string what = "DirectionalTree::refined(rho " + num(c.rho) + ", maxDepth " +
                                 std::to_string(c.maxDepth) + ") of a hand-made tree of total " + num(total) + ": ";
        CHECK_MESSAGE(std::abs(r.total() - total) < 1e-5 * total,
                      what << "the total must stay " << num(total) << ", got " << num(r.total()));
        // Every quadrant: its energy is the old tree's energy in its square; cut exactly where it
        // is above rho times the total (and not at maxDepth).
        int wrongEnergy = 0, wrongCut = 0, tooDeep = 0;
        std::string firstEnergy, firstCut;
        const double threshold = double(c.rho) * total;
        std::function<void(uint32_t, const Square&, int)> check = [&](uint32_t node, const Square& sq, int depth) {
            for (int i = 0; i < 4; ++i) {
                const Square q = sq.quadrant(i);
                const double want = energyIn(before, q), got = r.nodes[node].energy[i];
                if (std::abs(got - want) > 1e-5 * total && wrongEnergy++ == 0)
                    firstEnergy = "the quadrant at depth " + std::to_string(depth + 1) + " with corner (" + num(q.x) +
                                  ", " + num(q.y) + "): expected energy " + num(want) + ", got " + num(got);
                const bool cut = r.nodes[node].child[i] != 0;
                const bool shouldCut = want > threshold * (1.0 + 1e-6) && depth + 1 < c.maxDepth;
                const bool mayCut = want > threshold * (1.0 - 1e-6) && depth + 1 < c.maxDepth;
                if (depth + 1 > c.maxDepth) ++tooDeep;
                if ((cut && !mayCut) || (!cut && shouldCut))
                    if (wrongCut++ == 0)
                        firstCut = "the quadrant at depth " + std::to_string(depth + 1) + " with corner (" + num(q.x) +
                                   ", " + num(q.y) + ") and energy " + num(want) + " (threshold " + num(threshold) +
                                   ") is " + (cut ? "cut" : "a leaf");
                if (cut) check(r.nodes[node].child[i], q, depth + 1);
            }
        };
        check(0, Square(), 0);
        CHECK_MESSAGE(wrongEnergy == 0, what << wrongEnergy << " quadrants wrong; the first, " << firstEnergy);
        CHECK_MESSAGE(wrongCut == 0, what << wrongCut
                                          << " quadrants cut where they must not be or not cut where they must; the "
                                             "first, "
                                          << firstCut);
        CHECK_MESSAGE(tooDeep == 0, what << tooDeep << " quadrants deeper than maxDepth");
    }
    const ps::DirectionalTree empty;
    const ps::DirectionalTree re = empty.refined(0.01f, 16);
    CHECK_MESSAGE((re.nodes.size() == 1 && re.total() == 0.0f),
                  "DirectionalTree::refined of a tree without energy: expected it as it is (one node), got "
                      << re.nodes.size() << " nodes, total " << num(re.total()));
}
