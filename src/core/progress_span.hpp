// src/core/progress_span.hpp — the progress of one part of a call, as a share of the whole.
// A call made of parts (brushing's fill: growth, then the solver) hands each part a Progress
// that maps the part's fraction 0..1 onto [from, to] of the whole and renames the part's
// "done" (the whole is not done yet), so a listener sees the fraction only ever rise.
#pragma once

#include <string>
#include <utility>

#include "tessera/progress.hpp"

namespace tessera::core {

inline Progress progress_within(const Progress& whole, double from, double to, std::string part_done_stage) {
    if (!whole) return {};
    return [whole, from, to, stage = std::move(part_done_stage)](const ProgressEvent& part) {
        ProgressEvent e = part;
        e.fraction = from + (to - from) * part.fraction;
        if (e.stage == "done") e.stage = stage;
        return whole(e);
    };
}

}  // namespace tessera::core
