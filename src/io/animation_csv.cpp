// io/animation_csv.cpp — animations in CSV (docs/format.md, "Animations (frames)"): one row
// per sample per frame, with a frame column (an integer; the time column, if any, holds
// the frame's time stamp, else the time is the frame number) or a t column (the frame's
// time stamp). The rows are read and checked by the CSV reader (csv_format.cpp); here they
// are split into frames, in increasing order, and the elements of every frame are matched
// to those of the first by their element key (the element column, else the id), so that
// rows may come in any order. Errors name the file, the frame and the element, and the
// line where there is one.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/io_util.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"

namespace tessera {

using namespace io_detail;

namespace {

// The rows of one frame.
struct CsvFrame {
    std::string name;  // "frame 3" or "frame t = 0.5", for errors
    double time = 0.0;
    std::vector<const CsvRow*> rows;
};

// The first row of `a` whose sample id `b` does not hold (both sorted by sample id), or null.
const CsvRow* first_sample_not_in(const CsvGroup& a, const CsvGroup& b) {
    size_t j = 0;
    for (const CsvRow* row : a) {
        while (j < b.size() && b[j]->sample < row->sample) ++j;
        if (j == b.size() || b[j]->sample != row->sample) return row;
    }
    return nullptr;
}

class CsvAnimationReader {
public:
    CsvAnimationReader(const CsvTable& table, const std::string& source) : table_(table), source_(source) {}

    Animation read(const LoadOptions& options) const {
        check_columns();
        const std::vector<CsvFrame> frames = split_frames();
        const std::vector<CsvGroup> first = group_csv_rows(table_, frames.front().rows, source_);
        check_thread_samples(frames.front(), first);
        Animation a;
        a.structure = csv_elements(table_, first, source_);
        for (const CsvFrame& frame : frames) a.add_frame(frame.time, positions(frame, frames.front(), first));
        // The bounding box of every frame, so that no frame leaves the domain.
        a.structure.domain = csv_domain(a.positions, table_.dimension, options, source_);
        for (Sample& s : a.structure.samples) s.time = a.times.front();
        a.validate(source_);
        return a;
    }

private:
    const CsvTable& table_;
    const std::string& source_;

    void check_columns() const {
        const auto fail = [&](const std::string& what) { fail_input(source_, table_.header_line, what); };
        if (table_.frame && table_.t)
            fail(
                "columns frame and t cannot both be given (with frame, the time column holds the time "
                "stamps)");
        if (table_.t && table_.time)
            fail("columns t and time cannot both be given (t is the time stamp of the row's frame)");
        if (!table_.element && !table_.id)
            fail("a CSV with frames needs an element or id column, to match elements across frames");
    }

    // The rows by frame, in increasing order of frame number or t, with their time stamps.
    std::vector<CsvFrame> split_frames() const {
        std::map<double, CsvFrame> by_key;
        std::map<double, int> first_line;
        for (const CsvRow& row : table_.rows) {
            const double key = table_.frame ? static_cast<double>(row.frame) : row.t;
            const auto [it, added] = by_key.try_emplace(key);
            CsvFrame& frame = it->second;
            const double time = table_.frame ? (table_.time ? row.time : key) : row.t;
            if (added) {
                frame.name =
                    table_.frame ? "frame " + std::to_string(row.frame) : "frame t = " + format_number(row.t);
                frame.time = time;
                first_line[key] = row.line;
            } else if (time != frame.time) {
                fail_input(source_, row.line,
                           frame.name + " has time " + format_number(time) + " here but " +
                               format_number(frame.time) + " on line " + std::to_string(first_line[key]) +
                               " (one time stamp per frame)");
            }
            frame.rows.push_back(&row);
        }
        std::vector<CsvFrame> frames;
        for (auto& [key, frame] : by_key) {
            if (!frames.empty() && !(frame.time > frames.back().time))
                fail_input(source_, first_line[key],
                           frame.name + ": time stamps must strictly increase (" + frames.back().name +
                               " has time " + format_number(frames.back().time) + ", " + frame.name + " " +
                               format_number(frame.time) + ")");
            frames.push_back(std::move(frame));
        }
        return frames;
    }

    // CSV carries no topology, so a multi-sample element is a thread, whose samples are
    // numbered 0..n-1: a gap is a missing sample, which no frame could match.
    void check_thread_samples(const CsvFrame& frame, const std::vector<CsvGroup>& groups) const {
        if (!table_.sample) return;
        for (const CsvGroup& g : groups) {
            if (g.size() < 2) continue;
            for (size_t k = 0; k < g.size(); ++k) {
                const long long sample = g[k]->sample;
                if (sample == static_cast<long long>(k)) continue;
                fail_input(source_, g[k]->line,
                           frame.name + ": element '" + g[k]->element + "' has sample " +
                               std::to_string(sample) +
                               (sample < 0 ? std::string() : " but no sample " + std::to_string(k)) +
                               " (the samples of a multi-sample element, a thread, are numbered 0, 1, 2, ... "
                               "without gaps)");
            }
        }
    }

    // The sample positions of `frame`, in the order of the first frame's elements (`first`).
    std::vector<Vec3> positions(const CsvFrame& frame, const CsvFrame& first_frame,
                                const std::vector<CsvGroup>& first) const {
        const std::vector<CsvGroup> groups = group_csv_rows(table_, frame.rows, source_);
        std::map<std::string, const CsvGroup*> by_element;
        for (const CsvGroup& g : groups) {
            const auto [it, added] = by_element.emplace(g.front()->element, &g);
            if (!added)
                fail_input(source_, g.front()->line,
                           frame.name + ": element '" + g.front()->element +
                               "' appears twice (also on line " + std::to_string(it->second->front()->line) +
                               ")");
        }
        std::vector<Vec3> p;
        for (const CsvGroup& g0 : first) {
            const std::string& key = g0.front()->element;
            const auto it = by_element.find(key);
            if (it == by_element.end())
                fail_input(source_, 0,
                           frame.name + ": element '" + key +
                               "' is missing (every frame must hold the same elements)");
            const CsvGroup& g = *it->second;
            check_same_csv_element(*g0.front(), *g.front(), source_);
            check_same_samples(frame, first_frame, g0, g);
            for (const CsvRow* row : g) p.push_back(row->p);
            by_element.erase(it);
        }
        if (!by_element.empty()) {
            const CsvRow& row = *by_element.begin()->second->front();
            fail_input(source_, row.line,
                       frame.name + ": element '" + row.element + "' is not in " + first_frame.name +
                           " (every frame must hold the same elements)");
        }
        return p;
    }

    void check_same_samples(const CsvFrame& frame, const CsvFrame& first_frame, const CsvGroup& g0,
                            const CsvGroup& g) const {
        const std::string element = frame.name + ": element '" + g.front()->element + "'";
        const std::string rule = " (every frame must hold the same samples)";
        if (!table_.sample) {
            if (g.size() != g0.size())
                fail_input(source_, g.front()->line,
                           element + " has " + std::to_string(g.size()) + " samples, " + first_frame.name +
                               " has " + std::to_string(g0.size()) + rule);
            return;
        }
        if (const CsvRow* extra = first_sample_not_in(g, g0))
            fail_input(source_, extra->line,
                       element + " has sample " + std::to_string(extra->sample) + ", " + first_frame.name +
                           " has not" + rule);
        if (const CsvRow* missing = first_sample_not_in(g0, g))
            fail_input(source_, 0,
                       element + " has no sample " + std::to_string(missing->sample) + " (" +
                           first_frame.name + " has it on line " + std::to_string(missing->line) +
                           "; every frame must hold the same samples)");
    }
};

}  // namespace

Animation io_detail::read_csv_animation(CsvTable table, const std::string& source,
                                        const LoadOptions& options) {
    // Without an element column every row is an element, named by its id.
    if (!table.element)
        for (CsvRow& row : table.rows)
            if (row.id) row.element = std::to_string(*row.id);
    return CsvAnimationReader(table, source).read(options);
}

Animation parse_animation_csv(const std::string& text, const std::string& source,
                              const LoadOptions& options) {
    CsvTable table = read_csv_table(text, source);
    if (table.frame || table.t) return read_csv_animation(std::move(table), source, options);
    return animation_from_exemplar(read_csv_exemplar(table, source, options));
}

std::string animation_to_csv(const Animation& data) {
    std::string out = csv_header_line(data.structure, true);
    for (int f = 0; f < data.frame_count(); ++f)
        append_csv_rows(data.frame(f), true, std::to_string(f) + "," + format_number(data.times[f]) + ",",
                        out);
    return out;
}

}  // namespace tessera
