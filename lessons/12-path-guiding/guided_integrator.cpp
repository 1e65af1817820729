// Lesson 12 — the integrators "pt-guided" and "pt-guided-adrrs" (plumbing: read it, nothing to
// write here): lesson 3's path tracer (cameraWalk with its MIS visitor, misEmission and
// misLightSample) whose walk leaves every non-delta vertex by the guided mixture (a
// DirectionSampler: sampleGuided and guidedPdf with the sampling tree of the vertex's cell and
// side, Eq. 12.3), and which records what every sampled direction brought (radianceRecords,
// Eq. 12.12, 12.13) into the field it learns pass after pass (GuideField, Eq. 12.9, 12.11);
// "pt-guided-adrrs" adds roulette and splitting on the field as the walk's continuation rule
// (fieldDecision, Eq. 12.14, 12.15), lesson 3's roulette where the field cannot decide.
//
//   iteration i   belongs to pass k = floor(log2(i + 1)) (2^k iterations each); the first
//                 iteration of a pass ends the one before first (GuideField::endPass);
//   the last pass learns nothing (Müller et al. 2017, section 5.3): what it would learn no
//                 iteration would sample. With --spp it is the pass the render ends in (the image
//                 is the same as if it learnt); with --time, the pass after which the time left
//                 could not hold a pass twice as long: it samples its field to the deadline;
//   a pixel       one camera ray, its tree of paths depth first, all from the pixel's own generator
//                 (taskRng(seed, iteration, pixel)); its records go to its task's list;
//   after         the lists are added to the field in task order: the field, and every image after
//                 it, is the same for any number of threads.
#include <algorithm>
#include <cmath>
#include <sstream>
#include "12-path-guiding/guiding.h"
#include "errors.h"
#include "numbers.h"
#include "registry.h"
#include "tasks.h"

namespace ps {

namespace {

// A camera sample's vertices as radianceRecords wants them, built while the walk runs: the
// sampler appends an entry for every direction it samples (pending until the walk reaches the
// vertex it leads to, which fills it; one the roulette ended stays empty), the visitor one for
// every vertex no sampled direction led to (x_0, after a delta bounce).
struct SampleTree {
    std::vector<GuideVertex> vertices;
    std::vector<int> depth;     // the bounces of each entry's vertex
    std::vector<char> pending;  // sampled, not reached (yet)
    std::vector<int> onBranch;  // onBranch[b]: the entry of the current branch's vertex with b bounces
    // Empty again, its storage kept (one tree per task, reused by every camera ray of the task).
    void clear() {
        vertices.clear();
        depth.clear();
        pending.clear();
        onBranch.clear();
    }
    int at(int bounces) const {
        return bounces >= 0 && bounces < int(onBranch.size()) ? onBranch[size_t(bounces)] : -1;
    }
    // The entry of vertex v, which the walk has just reached.
    GuideVertex& reach(const WalkVertex& v) {
        int index;
        if (!vertices.empty() && pending.back() && depth.back() == v.bounces) {
            index = int(vertices.size()) - 1;
            pending.back() = 0;
        } else {
            GuideVertex g;
            g.from = at(v.bounces - 1);
            vertices.push_back(g);
            depth.push_back(v.bounces);
            pending.push_back(0);
            index = int(vertices.size()) - 1;
        }
        if (int(onBranch.size()) <= v.bounces) onBranch.resize(size_t(v.bounces) + 1, -1);
        onBranch[size_t(v.bounces)] = index;
        return vertices[size_t(index)];
    }
};

// The guided mixture as lesson 3's walk's direction sampler (Eq. 12.3, 12.4), recording each
// direction it samples into the camera sample's tree. The walk asks pdf (for its light sample's
// MIS) and sample at the same vertex: the cell and side of the last vertex asked are kept.
struct GuidedSampler : DirectionSampler {
    const GuideField* field = nullptr;
    SampleTree* tree = nullptr;
    mutable Vec3 lastP = Vec3(kInf), lastWo = Vec3(0.0f);
    mutable uint32_t lastCell = 0;
    mutable int lastSide = 0;

    const GuideSide& where(const WalkVertex& v) const {
        if (v.sp.p != lastP || v.wo != lastWo) {
            lastP = v.sp.p;
            lastWo = v.wo;
            lastCell = field->cellOf(v.sp.p);
            lastSide = AdjointCache::side(v.sp.n, v.wo);
        }
        return field->cell(lastCell).side[lastSide];
    }
    // alpha: the guide's share where the side's sampling tree was learnt from enough records
    // (GuideField::canGuide), else BSDF sampling alone.
    float alphaOf() const { return field->canGuide(lastCell, lastSide) ? kGuideFraction : 0.0f; }

    // The tree the mixture samples: where alpha is 0, an empty one (a constant density without a
    // descent: the mixture's density is then the BSDF's, to the last bit, and costs no more).
    static const DirectionalTree& guideOf(const GuideSide& s, float alpha) {
        static const DirectionalTree none;
        return alpha > 0.0f ? s.sampling : none;
    }

    bool sample(const Scene& scene, const WalkVertex& v, Rng& rng, BSDFSample& s) const override {
        const GuideSide& g = where(v);
        const float alpha = alphaOf();
        if (!sampleGuided(scene.materials[size_t(v.sp.material)], v.sp.n, v.wo, guideOf(g, alpha), alpha, rng, s))
            return false;
        if (!tree) return true;  // a pass that learns nothing keeps no tree
        GuideVertex x;
        x.from = tree->at(v.bounces);
        x.cell = int(lastCell);
        x.side = lastSide;
        x.wi = s.wi;
        x.pdf = s.pdf;
        x.throughput = v.beta * s.weight;
        tree->vertices.push_back(x);
        tree->depth.push_back(v.bounces + 1);
        tree->pending.push_back(1);
        return true;
    }
    float pdf(const Scene& scene, const WalkVertex& v, const Vec3& wi) const override {
        const GuideSide& g = where(v);
        const float alpha = alphaOf();
        return guidedPdf(scene.materials[size_t(v.sp.material)], v.sp.n, v.wo, guideOf(g, alpha), alpha, wi);
    }
};

struct DecisionCounts {
    uint64_t decisions = 0, roulette = 0, splits = 0;
    DecisionCounts& operator+=(const DecisionCounts& o) {
        decisions += o.decisions, roulette += o.roulette, splits += o.splits;
        return *this;
    }
};

// The pass of iteration i: floor(log2(i + 1)).
int passOf(uint32_t iteration) {
    int k = 0;
    while ((uint64_t(2) << k) <= uint64_t(iteration) + 1) ++k;
    return k;
}

// One camera ray's estimate (lesson 3's MIS visitor on the guided walk) and its records; with
// adrrs, the field's roulette and splitting as the walk's continuation rule.
Color guidedLi(const Scene& scene, const GuideField& field, bool adrrs, bool learn, const Ray& ray, Rng& rng,
               SampleTree& tree, std::vector<RadianceRecord>& records, DecisionCounts& counts) {
    const int maxDepth = scene.settings.maxDepth;
    tree.clear();
    GuidedSampler sampler;
    sampler.field = &field;
    sampler.tree = learn ? &tree : nullptr;
    WalkOptions opt(maxDepth);
    opt.sampler = &sampler;
    float I = -1.0f;
    int paths = 1;
    if (adrrs)
        opt.continuation = [&](const WalkVertex& v, Rng& r) {
            if (v.bounces == 0) I = fieldPixelEstimate(field, scene, v);
            const Decision d = fieldDecision(field, scene, v, I);
            if (!d.decided) return Continuations{1, v.beta};  // lesson 3's roulette after the bounce
            const float q = paths >= kMaxPathsPerCameraRay ? std::min(d.q, 1.0f) : d.q;
            ++counts.decisions;
            counts.roulette += q < 1.0f ? 1 : 0;
            counts.splits += q > 1.0f ? 1 : 0;
            Continuations c = continuations(v.beta, q, r);
            c.roulette = false;  // the rule decided survival here
            if (c.n > 0) paths += c.n - 1;
            return c;
        };
    Color L(0.0f);
    cameraWalk(scene, ray, rng, opt, [&](const WalkVertex& v) {
        if (!learn) {
            L += misEmission(scene, v) + misLightSample(scene, v, rng, maxDepth);
            return true;
        }
        GuideVertex& g = tree.reach(v);
        g.emitted = misEmission(scene, v);
        g.added = g.emitted + misLightSample(scene, v, rng, maxDepth);
        const int light = v.hit ? v.sp.light : scene.background;
        if (light >= 0)
            g.emittedFull = v.beta * (v.hit ? emittedRadiance(scene.lights[size_t(light)], v.sp.n, v.wo)
                                            : scene.backgroundRadiance());
        L += g.added;
        return true;
    });
    if (learn) radianceRecords(tree.vertices, records);
    return L;
}

}  // namespace

void GuidedPathTracer::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                       SampleStats& stats) {
    if (iteration == 0) {
        GuideSettings settings;
        if (budget_ > 0) settings.budget = budget_;
        field_ = GuideField(scene.bounds, settings);
        decisions_ = roulette_ = splits_ = 0;
        learning_ = true;
        lastPass_ = -1;
        passStart_ = secondsLeft();
    }
    const int pass = passOf(iteration);
    if (learning_ && (iteration == 0 || passOf(iteration - 1) != pass)) {
        if (iteration > 0) field_.endPass(pass - 1);
        const double left = secondsLeft(), before = passStart_ - left;  // the pass before took `before`
        passStart_ = left;
        const bool endsRender = iterationsLeft() >= 0 && uint64_t(iterationsLeft()) <= (uint64_t(1) << pass);
        const bool noTime = iteration > 0 && std::isfinite(left) && left < kLastPassRatio * before;
        if (endsRender || noTime) {
            learning_ = false;
            lastPass_ = pass;
            lastFrom_ = iteration;
        }
    }
    std::vector<std::vector<RadianceRecord>> lists(size_t(taskCount(out.width * out.height)));
    std::vector<DecisionCounts> counts(lists.size());
    std::vector<SampleTree> trees(lists.size());
    renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task& task) {
        const Vec2 raster = jitteredRaster(pixel, out.width, rng);
        return guidedLi(scene, field_, adrrs_, learning_, cameraRay(scene.camera, raster, rng), rng, trees[task.index],
                        lists[task.index], counts[task.index]);
    });
    for (size_t t = 0; t < lists.size(); ++t) {  // in task order
        field_.add(lists[t]);
        decisions_ += counts[t].decisions;
        roulette_ += counts[t].roulette;
        splits_ += counts[t].splits;
    }
}

std::vector<std::string> GuidedPathTracer::report() const {
    std::ostringstream s;
    s.precision(3);
    s << "field: " << field_.cells() << " cells after " << field_.passes() << " passes of " << field_.records()
      << " records, " << double(field_.bytes()) / double(1 << 20) << " MB";
    std::vector<std::string> lines = {s.str()};
    if (lastPass_ >= 0) {
        std::ostringstream l;
        l << "the last pass (" << lastPass_ << ", from iteration " << lastFrom_
          << " on) sampled the field without learning";
        lines.push_back(l.str());
    }
    if (adrrs_) {
        std::ostringstream d;
        d.precision(3);
        const double n = double(std::max<uint64_t>(decisions_, 1));
        d << decisions_ << " decisions on the field: " << 100.0 * double(roulette_) / n << " % roulette (q < 1), "
          << 100.0 * double(splits_) / n << " % splitting (q > 1)";
        lines.push_back(d.str());
    }
    return lines;
}

namespace {

struct GuidedADRRS : GuidedPathTracer {
    GuidedADRRS() : GuidedPathTracer(true) {}
};

// The algorithm option --guide-budget MB (framework/integrator.h): pt-guided and pt-guided-adrrs
// with a field of at most that many MB.
const char* const kBudgetHelp =
    R"(  --guide-budget MB  the most memory the learned field of pt-guided and pt-guided-adrrs may
                     take (lesson 12), in MB, from 0.01 to 65536 (default 64): the spatial tree
                     stops being cut and the learning trees are refined more coarsely once the
                     next pass would not fit
)";

std::vector<std::string> budgetAlgorithms() { return {"pt-guided", "pt-guided-adrrs"}; }

double budgetMB(const std::string& value) {
    double mb = 0.0;
    if (parseWhole(value, mb) != std::errc() || !(mb >= 0.01 && mb <= 65536.0))
        throw OptionError("option --guide-budget must be a number of MB from 0.01 to 65536, got '" + value + "'");
    return mb;
}
void checkBudget(const std::string& value) { (void)budgetMB(value); }

// makeIntegrator gives the result the algorithm's name and capabilities.
std::unique_ptr<Integrator> makeBudgeted(const std::string& algo, const std::string& value) {
    if (algo != "pt-guided" && algo != "pt-guided-adrrs") return nullptr;
    return std::make_unique<GuidedPathTracer>(algo == "pt-guided-adrrs", size_t(budgetMB(value) * double(1 << 20)));
}

[[maybe_unused]] const bool budgetRegistered = Registry<AlgorithmOption>::add(
    "guide-budget", AlgorithmOption{"MB", kBudgetHelp, budgetAlgorithms, checkBudget, makeBudgeted});

}  // namespace

PS_REGISTER_INTEGRATOR_CAPS(
    GuidedPathTracer, "pt-guided",
    "path tracing guided by a learned radiance field (SD-tree), mixed with BSDF sampling (lesson 12)",
    IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(GuidedADRRS, "pt-guided-adrrs",
                            "pt-guided with adjoint-driven roulette and splitting on the learned field (lesson 12)",
                            IntegratorCaps().withCameraModels());

}  // namespace ps
