// io/csv_format.cpp — CSV points: the format people already have (spreadsheets,
// digitised photographs, other tools), documented in docs/format.md.
// One row per sample; a header names the columns (any order, case-insensitive):
// x, y[, z], class, radius, angle, element + sample (multi-sample elements),
// qw,qx,qy,qz and scale (pose), id, time, locked; any other column is a free
// numeric attribute. Every error is one line "FILE:LINE: what", because a CSV
// with a problem on line 4711 is only fixable if the message says 4711.
//
// The writer emits exactly the columns the reader understands, with numbers in
// the shortest form that reads back exactly, so that to_csv -> parse_csv gives
// the same elements back (the domain and type flags are not part of CSV).
// Animations (a frame or t column) are assembled from the rows by animation_csv.cpp,
// through the pieces exposed in io_util.hpp; parse_csv gives their frame 0.
#include <algorithm>
#include <sstream>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "io/io_util.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera {

using namespace io_detail;

namespace {

enum class Column {
    x,
    y,
    z,
    cls,
    radius,
    angle,
    element,
    sample,
    qw,
    qx,
    qy,
    qz,
    scale,
    id,
    time,
    locked,
    frame,
    t,
    attribute
};

// Header names the reader recognises (lower case); everything else is an attribute.
const std::map<std::string, Column, std::less<>>& known_columns() {
    static const std::map<std::string, Column, std::less<>> columns = {{"x", Column::x},
                                                                       {"y", Column::y},
                                                                       {"z", Column::z},
                                                                       {"class", Column::cls},
                                                                       {"radius", Column::radius},
                                                                       {"angle", Column::angle},
                                                                       {"element", Column::element},
                                                                       {"sample", Column::sample},
                                                                       {"qw", Column::qw},
                                                                       {"qx", Column::qx},
                                                                       {"qy", Column::qy},
                                                                       {"qz", Column::qz},
                                                                       {"scale", Column::scale},
                                                                       {"id", Column::id},
                                                                       {"time", Column::time},
                                                                       {"locked", Column::locked},
                                                                       {"frame", Column::frame},
                                                                       {"t", Column::t}};
    return columns;
}

}  // namespace

// Fields may be double-quoted ("a, b" and "say ""hi""") so that class names with commas
// survive a round trip; quoted fields do not span lines.
std::vector<std::string> io_detail::split_csv_fields(std::string_view line, const std::string& source,
                                                     int line_number) {
    std::vector<std::string> fields;
    size_t i = 0;
    while (true) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::string field;
        if (i < line.size() && line[i] == '"') {
            ++i;
            bool closed = false;
            while (i < line.size()) {
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    closed = true;
                    ++i;
                    break;
                }
                field += line[i++];
            }
            if (!closed) fail_input(source, line_number, "unterminated quoted field");
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
            if (i < line.size() && line[i] != ',')
                fail_input(source, line_number, "unexpected text after a quoted field");
        } else {
            const size_t comma = line.find(',', i);
            field =
                std::string(trim(line.substr(i, comma == std::string_view::npos ? line.npos : comma - i)));
            i = comma == std::string_view::npos ? line.size() : comma;
        }
        fields.push_back(std::move(field));
        if (i >= line.size()) break;
        ++i;  // the comma
    }
    return fields;
}

namespace {

// Reads the header and the rows of a CSV file, each row checked on its own.
class CsvReader {
public:
    explicit CsvReader(const std::string& source) : source_(source) {}

    CsvTable read(std::string_view text) {
        // A UTF-8 byte order mark (spreadsheets write one) is not part of the first column name.
        if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
        CsvTable table;
        int line_number = 0;
        size_t start = 0;
        while (start <= text.size()) {
            const size_t end = std::min(text.find('\n', start), text.size());
            const std::string_view line = text.substr(start, end - start);
            ++line_number;
            start = end + 1;
            const std::string_view content = trim(line);
            if (content.empty() || content.front() == '#') continue;
            const auto fields = split_csv_fields(line, source_, line_number);
            if (table.header_line == 0) {
                read_header(fields, line_number);
                table.header_line = line_number;
            } else {
                table.rows.push_back(read_row(fields, line_number));
            }
        }
        if (table.rows.empty()) fail_input(source_, 0, "no elements (the exemplar is empty)");
        table.dimension = dimension_;
        table.attribute_names = attribute_names_;
        table.element = has(Column::element);
        table.sample = has(Column::sample);
        table.id = has(Column::id);
        table.time = has(Column::time);
        table.frame = has(Column::frame);
        table.t = has(Column::t);
        return table;
    }

private:
    std::string source_;
    std::vector<Column> roles_;
    std::vector<std::string> names_;  // column names as written in the header
    std::map<Column, size_t> index_;  // column role -> field index (known columns only)
    std::vector<size_t> attribute_fields_;
    std::vector<std::string> attribute_names_;
    int dimension_ = 2;

    bool has(Column c) const { return index_.count(c) > 0; }

    void read_header(const std::vector<std::string>& fields, int line) {
        std::set<std::string> seen;
        for (size_t f = 0; f < fields.size(); ++f) {
            const std::string name = fields[f];
            const std::string key = lower(name);
            if (name.empty()) fail_input(source_, line, "column " + std::to_string(f + 1) + " has no name");
            if (!seen.insert(key).second) fail_input(source_, line, "duplicate column '" + name + "'");
            const auto known = known_columns().find(key);
            const Column role = known == known_columns().end() ? Column::attribute : known->second;
            roles_.push_back(role);
            names_.push_back(role == Column::attribute ? name : key);
            if (role == Column::attribute) {
                attribute_fields_.push_back(f);
                attribute_names_.push_back(name);
            } else {
                index_[role] = f;
            }
        }
        if (!has(Column::x) || !has(Column::y))
            fail_input(source_, line, "the header needs columns x and y (got '" + join(fields) + "')");
        const int quaternion_columns =
            static_cast<int>(has(Column::qw)) + has(Column::qx) + has(Column::qy) + has(Column::qz);
        if (quaternion_columns != 0 && quaternion_columns != 4)
            fail_input(source_, line, "columns qw, qx, qy, qz must appear together");
        if (has(Column::sample) && !has(Column::element))
            fail_input(source_, line, "a sample column needs an element column to say which element");
        dimension_ = has(Column::z) ? 3 : 2;
    }

    static std::string join(const std::vector<std::string>& fields) {
        std::string out;
        for (size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + fields[i];
        return out;
    }

    double number(const std::vector<std::string>& fields, size_t f, int line) const {
        const auto value = parse_number(fields[f]);
        if (!value) fail_input(source_, line, names_[f] + " is not a number: '" + fields[f] + "'");
        if (!std::isfinite(*value)) {
            const Column role = roles_[f];
            const bool coordinate = role == Column::x || role == Column::y || role == Column::z;
            fail_input(source_, line,
                       coordinate ? "coordinate is NaN or infinite" : names_[f] + " is NaN or infinite");
        }
        return *value;
    }

    double number(const std::vector<std::string>& fields, Column c, int line) const {
        return number(fields, index_.at(c), line);
    }

    // An integer column (sample, frame).
    long long integer(const std::vector<std::string>& fields, Column c, const char* name, int line) const {
        const double value = number(fields, c, line);
        if (value != std::floor(value) || std::abs(value) > 1e15)
            fail_input(source_, line, std::string(name) + " is not an integer: '" + fields[index_.at(c)] + "'");
        return static_cast<long long>(value);
    }

    CsvRow read_row(const std::vector<std::string>& fields, int line) const {
        if (fields.size() != roles_.size())
            fail_input(source_, line,
                       "expected " + std::to_string(roles_.size()) + " fields, got " +
                           std::to_string(fields.size()));
        CsvRow row;
        row.line = line;
        row.p.x = number(fields, Column::x, line);
        row.p.y = number(fields, Column::y, line);
        if (has(Column::z)) row.p.z = number(fields, Column::z, line);
        if (has(Column::cls)) {
            row.cls = fields[index_.at(Column::cls)];
            if (row.cls.empty()) fail_input(source_, line, "class is empty");
        }
        if (has(Column::element)) {
            row.element = fields[index_.at(Column::element)];
            if (row.element.empty()) fail_input(source_, line, "element is empty");
        }
        if (has(Column::sample)) row.sample = integer(fields, Column::sample, "sample", line);
        if (has(Column::frame)) row.frame = integer(fields, Column::frame, "frame", line);
        if (has(Column::t)) row.t = number(fields, Column::t, line);
        // An empty radius field means "no radius" (the writer leaves it empty for such
        // elements when others have one); an explicit value must be a real radius.
        if (has(Column::radius) && !fields[index_.at(Column::radius)].empty()) {
            row.radius = number(fields, Column::radius, line);
            if (!(row.radius > 0.0))
                fail_input(source_, line,
                           "radius must be > 0 (got " + fields[index_.at(Column::radius)] + ")");
        }
        if (has(Column::angle)) row.angle = number(fields, Column::angle, line);
        if (has(Column::qw))
            row.q = Quat{number(fields, Column::qw, line), number(fields, Column::qx, line),
                         number(fields, Column::qy, line), number(fields, Column::qz, line)};
        if (has(Column::scale)) {
            row.scale = number(fields, Column::scale, line);
            if (!(row.scale > 0.0))
                fail_input(source_, line, "scale must be > 0 (got " + fields[index_.at(Column::scale)] + ")");
        }
        if (has(Column::id)) row.id = unsigned_integer(fields[index_.at(Column::id)], "id", line);
        if (has(Column::time)) row.time = number(fields, Column::time, line);
        if (has(Column::locked)) row.locked = boolean(fields[index_.at(Column::locked)], "locked", line);
        for (size_t f : attribute_fields_) {
            const auto value = parse_number(fields[f]);
            if (!value)
                fail_input(source_, line,
                           names_[f] + " is not a number: '" + fields[f] +
                               "' (columns other than the known ones are numeric attributes" +
                               (has(Column::cls) ? std::string(")")
                                                 : "; name it 'class' if it holds class names)"));
            if (!std::isfinite(*value)) fail_input(source_, line, names_[f] + " is NaN or infinite");
            row.attributes.push_back(*value);
        }
        return row;
    }

    std::uint64_t unsigned_integer(const std::string& field, const std::string& name, int line) const {
        std::uint64_t value = 0;
        const char* end = field.data() + field.size();
        const auto [ptr, ec] = std::from_chars(field.data(), end, value);
        if (field.empty() || ec != std::errc() || ptr != end)
            fail_input(source_, line, name + " is not a non-negative integer: '" + field + "'");
        return value;
    }

    bool boolean(const std::string& field, const std::string& name, int line) const {
        const std::string value = lower(field);
        if (value == "1" || value == "true") return true;
        if (value == "0" || value == "false" || value.empty()) return false;
        fail_input(source_, line, name + " must be 0, 1, true or false: '" + field + "'");
    }
};

}  // namespace

// Rows of one element must agree on everything that belongs to the element.
void io_detail::check_same_csv_element(const CsvRow& first, const CsvRow& row, const std::string& source) {
    const auto differ = [&](const char* what) {
        fail_input(source, row.line,
                   "element '" + row.element + "' has a different " + what + " than on line " +
                       std::to_string(first.line));
    };
    if (row.cls != first.cls) differ("class");
    if (row.radius != first.radius) differ("radius");
    if (row.angle != first.angle) differ("angle");
    if (row.q != first.q) differ("orientation (qw, qx, qy, qz)");
    if (row.scale != first.scale) differ("scale");
    if (row.id != first.id) differ("id");
    if (row.locked != first.locked) differ("locked");
    if (row.attributes != first.attributes) differ("attribute value");
}

std::vector<CsvGroup> io_detail::group_csv_rows(const CsvTable& table, const std::vector<const CsvRow*>& rows,
                                                const std::string& source) {
    std::vector<CsvGroup> groups;
    if (!table.element) {
        for (const CsvRow* row : rows) groups.push_back({row});
        return groups;
    }
    std::map<std::string, size_t> group_of;
    for (const CsvRow* row : rows) {
        const auto [it, added] = group_of.try_emplace(row->element, groups.size());
        if (added)
            groups.emplace_back();
        else
            check_same_csv_element(*groups[it->second].front(), *row, source);
        groups[it->second].push_back(row);
    }
    if (table.sample) {
        for (auto& g : groups) {
            std::stable_sort(g.begin(), g.end(), [](const CsvRow* a, const CsvRow* b) { return a->sample < b->sample; });
            for (size_t s = 1; s < g.size(); ++s)
                if (g[s]->sample == g[s - 1]->sample)
                    fail_input(source, std::max(g[s]->line, g[s - 1]->line),
                               "element '" + g[s]->element + "' has sample " + std::to_string(g[s]->sample) +
                                   " twice (also on line " + std::to_string(std::min(g[s]->line, g[s - 1]->line)) +
                                   ")");
        }
    }
    return groups;
}

Exemplar io_detail::csv_elements(const CsvTable& table, const std::vector<CsvGroup>& groups,
                                 const std::string& source) {
    Exemplar ex;
    ex.dimension = table.dimension;
    ex.attribute_names = table.attribute_names;
    std::set<std::uint64_t> ids;
    for (const auto& g : groups) {
        const CsvRow& first = *g.front();
        std::vector<Vec3> points;
        for (const CsvRow* row : g) points.push_back(row->p);
        const int index = ex.add_element(ex.type_index(first.cls), points, first.radius);
        Element& e = ex.elements[index];
        if (const auto problem = resolve_orientation(first.q, first.angle, table.dimension, e.orientation))
            fail_input(source, first.line, *problem);
        e.scale = first.scale;
        if (first.id) e.id = *first.id;
        if (!ids.insert(e.id).second) fail_input(source, first.line, "duplicate element id " + std::to_string(e.id));
        e.locked = first.locked;
        e.attributes = first.attributes;
        for (size_t s = 0; s < g.size(); ++s) ex.samples[e.first_sample + s].time = g[s]->time;
    }
    return ex;
}

Domain io_detail::csv_domain(const std::vector<Vec3>& points, int dimension, const LoadOptions& options,
                             const std::string& source) {
    if (options.input_domain) {
        if (options.input_domain->dimension() != dimension)
            throw Error(ErrorKind::domain, source + ": the input domain is " +
                                               std::to_string(options.input_domain->dimension()) +
                                               "D but the data are " + std::to_string(dimension) + "D");
        // A window around none of the points is another axis range or a typo, not data; one
        // that leaves some out would make an exemplar with elements outside its own domain
        // (neighbourhoods and densities measured against a window they do not fit).
        const auto outside = std::count_if(points.begin(), points.end(),
                                           [&](const Vec3& p) { return !options.input_domain->inside(p); });
        if (!points.empty() && outside == static_cast<long>(points.size()))
            throw Error(ErrorKind::domain, source + ": none of its " + std::to_string(points.size()) +
                                               " points lies in the input domain");
        if (outside > 0) {
            const Vec3 first = *std::find_if(points.begin(), points.end(),
                                             [&](const Vec3& p) { return !options.input_domain->inside(p); });
            std::ostringstream text;
            text << source << ": " << outside << " of its " << points.size()
                 << " points lie outside the input domain (the first at " << first.x << "," << first.y;
            if (dimension == 3) text << "," << first.z;
            text << "); crop the file or give a window that holds them";
            throw Error(ErrorKind::domain, text.str());
        }
        return *options.input_domain;
    }
    Vec3 lo = points.front(), hi = lo;
    for (const Vec3& p : points)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    try {
        return Domain::box(lo, hi, dimension);
    } catch (const Error& e) {
        throw Error(ErrorKind::domain, source + ": the bounding box of the points cannot be the domain (" + e.what() +
                                           "); give the input domain explicitly");
    }
}

namespace {

// ---- writing ---------------------------------------------------------------

// Quotes a text field when it would otherwise not read back as itself.
std::string text_field(const std::string& value, const std::string& what) {
    if (value.find_first_of("\n\r") != std::string::npos)
        throw Error(ErrorKind::input, "cannot write CSV: " + what + " '" + value + "' contains a line break");
    const bool plain = !value.empty() && value.find_first_of(",\"") == std::string::npos &&
                       trim(value).size() == value.size() && value.front() != '#';
    if (plain) return value;
    std::string out = "\"";
    for (char c : value) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// Attribute columns must not be mistaken for known columns or for each other on reading.
void check_attribute_names(const Exemplar& data) {
    std::set<std::string> seen;
    for (const auto& name : data.attribute_names) {
        const std::string key = lower(name);
        if (known_columns().count(key))
            throw Error(ErrorKind::input,
                        "cannot write CSV: attribute '" + name + "' has the name of a CSV column");
        if (!seen.insert(key).second)
            throw Error(ErrorKind::input, "cannot write CSV: attribute names '" + name +
                                              "' differ only in case (CSV ignores case)");
    }
}

// The columns the writer writes for some data.
struct CsvLayout {
    bool three_d = false;
    bool frame = false;    // frame,time columns in front (an animation's frame)
    bool element = false;  // element,sample columns
    bool radius = false, locked = false, time = false;

    CsvLayout(const Exemplar& data, bool frame_columns) : three_d(data.dimension == 3), frame(frame_columns) {
        element = frame || data.has_multi_sample_elements();
        for (const auto& e : data.elements) {
            radius = radius || e.radius > 0.0;
            locked = locked || e.locked;
        }
        // In an animation, time is the frame's, in the frame's time column.
        for (const auto& s : data.samples) time = time || (!frame && s.time != 0.0);
    }
};

}  // namespace

Exemplar parse_csv(const std::string& text, const std::string& source, const LoadOptions& options) {
    CsvTable table = read_csv_table(text, source);
    if (table.frame || table.t) return read_csv_animation(std::move(table), source, options).frame(0);
    return read_csv_exemplar(table, source, options);
}

CsvTable io_detail::read_csv_table(std::string_view text, const std::string& source) {
    return CsvReader(source).read(text);
}

Exemplar io_detail::read_csv_exemplar(const CsvTable& table, const std::string& source, const LoadOptions& options) {
    std::vector<const CsvRow*> rows;
    for (const CsvRow& row : table.rows) rows.push_back(&row);
    Exemplar ex = csv_elements(table, group_csv_rows(table, rows, source), source);
    std::vector<Vec3> points;
    for (const Sample& s : ex.samples) points.push_back(s.p);
    ex.domain = csv_domain(points, table.dimension, options, source);
    ex.validate(source);
    return ex;
}

std::string to_csv(const Exemplar& data) {
    std::string out = csv_header_line(data, false);
    append_csv_rows(data, false, "", out);
    return out;
}

std::string io_detail::csv_header_line(const Exemplar& data, bool frame_columns) {
    check_attribute_names(data);
    const CsvLayout layout(data, frame_columns);
    std::string out;
    if (layout.frame) out += "frame,time,";
    if (layout.element) out += "element,sample,";
    out += layout.three_d ? "x,y,z,class" : "x,y,class";
    if (layout.radius) out += ",radius";
    out += layout.three_d ? ",qw,qx,qy,qz" : ",angle";
    out += ",scale,id";
    if (layout.time) out += ",time";
    if (layout.locked) out += ",locked";
    for (const auto& name : data.attribute_names) out += "," + text_field(name, "attribute name");
    out += "\n";
    return out;
}

void io_detail::append_csv_rows(const Exemplar& data, bool frame_columns, const std::string& row_lead,
                                std::string& out) {
    const CsvLayout layout(data, frame_columns);
    const auto num = [](double v) { return format_number(v); };
    for (const auto& e : data.elements) {
        // The element's columns are the same on each of its rows.
        std::string pose = "," + text_field(data.types.at(static_cast<size_t>(e.type)).name, "class name");
        if (layout.radius) pose += "," + (e.radius > 0.0 ? num(e.radius) : std::string());
        const Quat& q = e.orientation;
        pose += layout.three_d ? "," + num(q.w) + "," + num(q.x) + "," + num(q.y) + "," + num(q.z)
                               : "," + num(q.angle_z());
        pose += "," + num(e.scale) + "," + std::to_string(e.id);
        std::string tail;
        if (layout.locked) tail += e.locked ? ",1" : ",0";
        for (double a : e.attributes) tail += "," + num(a);
        for (int s = 0; s < e.sample_count; ++s) {
            const Sample& sample = data.samples[e.first_sample + s];
            out += row_lead;
            if (layout.element) out += std::to_string(e.id) + "," + std::to_string(s) + ",";
            out += num(sample.p.x) + "," + num(sample.p.y);
            if (layout.three_d) out += "," + num(sample.p.z);
            out += pose;
            if (layout.time) out += "," + num(sample.time);
            out += tail;
            out += "\n";
        }
    }
}

}  // namespace tessera
