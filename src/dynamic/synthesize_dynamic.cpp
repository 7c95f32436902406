// dynamic/synthesize_dynamic.cpp — frame-by-frame synthesis (section 4.1, Figure 4): the
// first frame by the static method, each later frame advected along the matched input
// motion (plus the global flow) and then optimised by search and assignment against
// temporal-causal neighbourhoods.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "core/parallel.hpp"
#include "core/progress_span.hpp"
#include "dynamic/graph_exemplar.hpp"
#include "dynamic/input_frames.hpp"
#include "dynamic/collision_step.hpp"
#include "dynamic/frame_search.hpp"
#include "dynamic/obstacle_flow.hpp"
#include "dynamic/output_frames.hpp"
#include "dynamic/synthesize_all_frames.hpp"
#include "dynamic/void_closing.hpp"
#include "tessera/det.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace dynamic;

constexpr int similarity_k = 4;     // size of the k-coherence sets
constexpr int similarity_scan = 64; // input sample-frames scanned to build each set

void check_inputs(const Animation& exemplar, const Domain& domain, const DynamicOptions& options) {
    check_options(dynamic_option_table(), options);
    exemplar.validate("exemplar");
    if (exemplar.structure.has_multi_sample_elements())
        throw Error(ErrorKind::input,
                    "exemplar: frame-by-frame synthesis takes single-sample elements (particles, agents); "
                    "threads and sheets follow a coarse motion (--coarse)");
    if (domain.dimension() != exemplar.structure.dimension)
        throw Error(ErrorKind::domain, "the output domain is " + std::to_string(domain.dimension()) +
                                           "D but the exemplar is " + std::to_string(exemplar.structure.dimension) + "D");
    if (exemplar.frame_count() < options.temporal_size)
        throw Error(ErrorKind::option, "temporal_size must be at most the exemplar's frame count (" +
                                           std::to_string(exemplar.frame_count()) + "), got " +
                                           std::to_string(options.temporal_size));
}

StParams resolve_params(const Animation& exemplar, const DynamicOptions& options) {
    StParams p;
    const Exemplar first = exemplar.frame(options.temporal_size - 1);
    p.dimension = first.dimension;
    p.shape = options.shape;
    p.temporal = options.temporal_size;
    p.spacing = nearest_neighbor_distances(first, options.threads).mean;
    if (!(p.spacing > 0.0)) throw Error(ErrorKind::input, "exemplar: its elements have no spacing (all coincide)");
    // The 1-ring (paper, section 6: "approximately cover the 1-ring neighborhood").
    p.radius = options.radius > 0.0 ? options.radius : 1.5 * p.spacing;
    // A pair displaced by half a spacing is as bad as none; input entries further than that
    // beyond r can pair with nothing, so input neighbourhoods stop there.
    const double cap = p.spacing;
    p.input_radius = p.radius + cap;
    p.cap2 = cap * cap;
    p.alpha = options.alpha >= 0.0 ? options.alpha : p.spacing * p.spacing;
    if (options.sigma_p > 0.0) p.inv_sigma_p2 = 1.0 / (options.sigma_p * p.radius * options.sigma_p * p.radius);
    if (options.sigma_t > 0.0) p.inv_sigma_t2 = 1.0 / (options.sigma_t * options.sigma_t);
    return p;
}

// The first frame: the static method on the exemplar's first frame with a full window.
Arrangement first_frame(const Animation& exemplar, const Domain& domain, const DynamicOptions& options,
                        const Progress& progress) {
    DetOptions det;
    det.seed = options.seed;
    det.threads = options.threads;
    // Its stages are reported as parts of "first frame" ("first frame: iteration 3/10").
    const Progress renamed = !progress ? Progress{} : Progress{[progress](const ProgressEvent& e) {
        ProgressEvent r = e;
        if (e.stage != "done") r.stage = "first frame: " + e.stage;
        return progress(r);
    }};
    return synthesize_det(exemplar.frame(options.temporal_size - 1), domain, det, renamed);
}

std::vector<int> sample_types(const Arrangement& first, const Exemplar& exemplar) {
    std::vector<int> types(first.samples.size());
    for (size_t s = 0; s < types.size(); ++s) {
        const std::string& name = first.types[first.elements[first.samples[s].element].type].name;
        types[s] = exemplar.find_type(name);
    }
    return types;
}

// Moves a sample that left the domain back in: wrap re-enters it on the far side of the
// bounding box (its shift moves with it, so its detail trail stays continuous); whatever is
// still outside (an obstacle, a shaped domain) goes to the nearest point inside.
void keep_inside(Vec3& p, Vec3& shift, const Domain& domain, bool wrap) {
    if (wrap) {
        const Box& box = domain.bounds();
        for (int k = 0; k < domain.dimension(); ++k) {
            const double extent = box.hi[k] - box.lo[k];
            const double turns = std::floor((p[k] - box.lo[k]) / extent);
            if (turns != 0.0) p[k] -= turns * extent, shift[k] -= turns * extent;
        }
    }
    if (!domain.inside(p)) p = domain.closest_inside(p);
}

// Advection (section 4.1, "Initialization"): every sample follows the blended motion of its
// matches (Eq. 11) and the flow; its matches move on to their next input frame.
void advect(const InputFrames& input, OutputFrames& out, const ObstacleFlow& flow, const Vec3& flow_step,
            const Domain& domain, bool wrap) {
    const int frame = out.frame();
    for (int s = 0; s < out.size(); ++s) {
        Vec3 motion;
        double weight = 0.0;
        for (int j = 0; j < out.matches(); ++j) {
            const int m = out.match(s)[j];
            if (m < 0) continue;
            motion += input.motion(m) * out.omega(s)[j];
            weight += out.omega(s)[j];
            if (input.next(m) >= 0) out.match(s)[j] = input.next(m);
        }
        if (weight > 0.0) motion = motion / weight;
        // The flow where the sample is: the far flow, bent round the domain's obstacles.
        const Vec3 carried = flow.displacement(out.past(frame - 1, s), flow_step);
        Vec3 p = out.past(frame - 1, s) + motion + carried;
        Vec3 shift = out.past_shift(frame - 1, s) + carried;
        keep_inside(p, shift, domain, wrap);
        out.current()[s] = p;
        out.current_shift()[s] = shift;
    }
}

// One run: the input index, the output's frames and the search's buffers, made once.
class FrameByFrame {
public:
    FrameByFrame(const Animation& exemplar, const Domain& domain, const DynamicOptions& options,
                 const StParams& params, const Arrangement& first)
        : domain_(domain),
          options_(options),
          params_(params),
          input_(exemplar, params, options.threads),
          out_(params.dimension, sample_types(first, exemplar.structure), options.matches, params,
               periodic_of(domain, options)),
          flow_(domain, options.threads, squared_norm(options.flow) > 0.0),
          scratch_(core::resolve_threads(options.threads)),
          settings_{options.search, options.random_candidates, options.seed, 0, true} {
        if (options.search == SearchMode::kcoherence)
            build_similarity(input_, params, similarity_k, similarity_scan, options.seed, options.threads);
        for (size_t s = 0; s < first.samples.size(); ++s) out_.current()[s] = first.samples[s].p;
        if (options.physics) collisions_.emplace(exemplar, domain, options.wrap);
        if (!options.keep_voids)
            voids_.emplace(exemplar, domain, params.spacing, periodic_of(domain, options));
        // A box that wraps has no walls: nothing to weigh, and no point paying the test.
        const bool walls = !(options.wrap && domain.kind() == Domain::Kind::box);
        settings_.domain = walls ? &domain : nullptr;
        settings_.wrap = options.wrap;
        settings_.lambda = params.spacing * params.spacing;  // as the static method's default
    }

    // Frame 0, the static method's arrangement as it is (with physics, its collisions
    // resolved): matched to the exemplar's first full window (only its spatial group). Returns the energy of the match.
    double first_frame() {
        if (options_.physics) resolve_collisions();  // settled before it is shown, not at frame 1
        out_.index();
        const double energy = search_frame(input_, out_, params_, settings_, scratch_, options_.threads);
        settings_.first_frame_only = false;
        return energy;
    }

    // The next frame: advection, then the rounds of search and assignment. Returns the last
    // search's energy.
    double next_frame(const Vec3& flow_step) {
        advect(input_, out_, flow_, flow_step, domain_, options_.wrap);
        // The voids are closed before the rounds too: once after them, the assignment pulled
        // the moved rim back towards its neighbours (the void past the obstacle held on).
        if (voids_) close_voids();
        if (options_.physics) resolve_collisions();
        double energy = 0.0;
        for (int round = 0; round < options_.iterations; ++round) {
            settings_.round = round;
            out_.index();
            energy = search_frame(input_, out_, params_, settings_, scratch_, options_.threads);
            assign_frame(out_, params_.radius, options_.threads);
            for (int s = 0; s < out_.size(); ++s)
                keep_inside(out_.current()[s], out_.current_shift()[s], domain_, options_.wrap);
        }
        if (voids_) close_voids();
        if (options_.physics && options_.iterations > 0) resolve_collisions();
        return energy;
    }

    // The frame just made, as positions; then the next frame starts from it.
    const std::vector<Vec3>& positions() const { return out_.current(); }
    void commit() { out_.commit(); }
    // What the void closing did over the run, for the stats' notes ("" when it moved nothing).
    std::string void_note(int frames) const {
        if (!voids_ || moved_ == 0) return "";
        return "voids wider than the exemplar's (" + std::to_string(voids_->exemplar_void()) +
               ") closed from their rim: " + std::to_string(moved_) + " sample moves over " +
               std::to_string(frames) + " frames";
    }

private:
    // The extra step of void_closing.hpp: the rim of each void too wide moves in a little.
    void close_voids() {
        moved_ += voids_->apply(out_.current());
        for (int s = 0; s < out_.size(); ++s)
            keep_inside(out_.current()[s], out_.current_shift()[s], domain_, options_.wrap);
    }

    // The physics sub-step (Figure 5): what it moves is detail motion, so the samples'
    // flow shifts stay; a sample pushed across the wrap seam re-enters as advection's do.
    void resolve_collisions() {
        collisions_->apply(out_.current());
        for (int s = 0; s < out_.size(); ++s)
            keep_inside(out_.current()[s], out_.current_shift()[s], domain_, options_.wrap);
    }

    static Periodic periodic_of(const Domain& domain, const DynamicOptions& options) {
        if (!options.wrap) return {};
        return {true, domain.bounds().lo, domain.bounds().size()};
    }

    const Domain& domain_;
    const DynamicOptions& options_;
    StParams params_;
    InputFrames input_;
    OutputFrames out_;
    ObstacleFlow flow_;
    std::optional<CollisionStep> collisions_;  // the physics sub-step, when asked for
    std::optional<VoidClosing> voids_;         // the void closing, unless turned off
    long moved_ = 0;                           // samples it moved, over the run
    std::vector<SearchScratch> scratch_;
    SearchSettings settings_;
};

// The flow at time t after the first frame: turned by flow_turn degrees per unit of time
// about z (taken at the middle of each frame step, so a turn is not late by half a step).
Vec3 flow_at(const DynamicOptions& options, double t) {
    if (options.flow_turn == 0.0) return options.flow;
    const double a = options.flow_turn * std::numbers::pi / 180.0 * t;
    const Vec3& v = options.flow;
    return {v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a), v.z};
}

// The exemplar's mean frame step: the output's frames are that far apart.
double frame_interval(const Animation& exemplar) {
    const int n = exemplar.frame_count();
    return n > 1 ? (exemplar.times.back() - exemplar.times.front()) / (n - 1) : 1.0;
}

}  // namespace

AnimatedArrangement synthesize_dynamic(const Animation& given, const Domain& domain, const DynamicOptions& options,
                                       const Progress& progress) {
    // All frames together (section 4.1, all-frame sequencing): synthesize_all_frames.cpp.
    if (options.sequencing == Sequencing::all) return dynamic::synthesize_all_frames(given, domain, options, progress);
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    // A still gets its motion from graph synthesis first (section 4.3, graph_exemplar.cpp).
    check_options(dynamic_option_table(), options);
    std::optional<Animation> enriched;
    std::vector<std::string> graph_notes;
    const Animation& exemplar = dynamic::exemplar_with_motion(given, options, enriched, graph_notes);
    check_inputs(exemplar, domain, options);
    const StParams params = resolve_params(exemplar, options);
    const int frames = options.frames > 0 ? options.frames : std::max(2, exemplar.frame_count());
    const double dt = frame_interval(exemplar);

    const Arrangement first =
        first_frame(exemplar, domain, options, core::progress_within(progress, 0.0, 0.2, "first frame"));
    FrameByFrame run(exemplar, domain, options, params, first);
    AnimatedArrangement result;
    result.stats.method = "dynamic";
    result.stats.notes = graph_notes;
    result.stats.radius = params.radius;
    result.stats.seed = options.seed;
    result.stats.threads = core::resolve_threads(options.threads);
    result.structure = static_cast<const Exemplar&>(first);
    result.stats.energy.push_back(run.first_frame());
    result.add_frame(exemplar.times.front(), run.positions());
    run.commit();
    result.stats.init_seconds = elapsed();  // the first frame, the input index and the k-coherence sets
    for (int f = 1; f < frames; ++f) {
        const double frame_start = elapsed();
        const double energy = run.next_frame(flow_at(options, (f - 0.5) * dt) * dt);
        result.stats.energy.push_back(energy);
        result.stats.iteration_seconds.push_back(elapsed() - frame_start);
        result.add_frame(exemplar.times.front() + f * dt, run.positions());
        run.commit();
        if (progress && !progress(ProgressEvent{"frame", f, frames, energy, elapsed(), 0.2 + 0.8 * (f + 1) / frames}))
            throw Cancelled();
    }
    if (const std::string note = run.void_note(frames); !note.empty()) result.stats.notes.push_back(note);
    for (Sample& s : result.structure.samples) s.time = result.times.front();
    result.stats.final_energy = result.stats.energy.back();
    result.stats.total_seconds = elapsed();
    if (progress) progress(ProgressEvent{"done", frames - 1, frames, result.stats.final_energy, elapsed(), 1.0});
    return result;
}

}  // namespace tessera
