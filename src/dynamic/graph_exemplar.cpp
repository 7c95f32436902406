// dynamic/graph_exemplar.cpp — graph synthesis as the dynamic method's first step for a still.
#include "dynamic/graph_exemplar.hpp"

#include <cstdio>

#include "core/option_rows.hpp"
#include "tessera/error.hpp"
#include "tessera/graph_motion.hpp"

namespace tessera {

namespace {

constexpr int automatic_graph_frames = 24;  // enough for a path of 6 steps to be smooth (4 frames a step)

std::string refused_one(const std::string& as_written) {
    return as_written + " must be -1 (automatic), 0 (off) or an integer >= 2, got 1";
}

}  // namespace

int graph_frames_for(const Animation& exemplar, const DynamicOptions& options) {
    if (options.graph_frames < 0) return exemplar.frame_count() == 1 ? automatic_graph_frames : 0;
    return options.graph_frames;
}

namespace dynamic {

OptionSpec<DynamicOptions> graph_frames_row() {
    OptionSpec<DynamicOptions> row = options::integer_row<DynamicOptions>(
        "graph_frames",
        "Graph synthesis (section 4.3): frames the exemplar is continued to before synthesis, a still given "
        "motion, a short clip continued from its last frame through the neighbourhoods of all its frames; -1 = "
        "automatic (24 for a one-frame exemplar, else off), 0 = off.",
        [](auto& o) -> auto& { return o.graph_frames; }, options::between(-1, 100000));
    row.set = [set = row.set](DynamicOptions& o, const OptionValue& v, const OptionContext& context) {
        if (std::get<std::int64_t>(v) == 1) throw Error(ErrorKind::option, refused_one(context.as_written));
        set(o, v, context);
    };
    return row;
}

void check_graph_frames(const DynamicOptions& options) {
    if (options.graph_frames == 1) throw Error(ErrorKind::option, refused_one("graph_frames"));
}

const Animation& exemplar_with_motion(const Animation& given, const DynamicOptions& options,
                                      std::optional<Animation>& storage, std::vector<std::string>& notes) {
    check_graph_frames(options);
    const int frames = graph_frames_for(given, options);
    if (frames == 0) return given;
    given.validate("exemplar");
    GraphMotionOptions graph;
    graph.frames = frames;
    graph.radius = options.radius;
    graph.seed = options.seed;
    graph.threads = options.threads;
    GraphMotionStats stats;
    if (frames <= given.frame_count()) {
        notes.push_back("graph synthesis: the exemplar has " + std::to_string(given.frame_count()) +
                        " frames, graph_frames " + std::to_string(frames) + " adds none");
        return given;
    }
    storage = extend_by_graph(given, graph, &stats);
    char line[240];
    std::snprintf(line, sizeof line,
                  "graph synthesis gave the %s %d frames (%d paths of %.1f steps on average, mean motion %.3f "
                  "spacings per frame, %.2f s)",
                  given.frame_count() == 1 ? "still" : "clip", frames, given.sample_count() - stats.still_samples,
                  stats.path_steps, stats.mean_speed, stats.seconds);
    notes.push_back(line);
    notes.insert(notes.end(), stats.notes.begin(), stats.notes.end());
    return *storage;
}

}  // namespace dynamic

}  // namespace tessera
