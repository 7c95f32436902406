// Test helper: reads the real point patterns of tests/data/spatstat (spatstat.data field
// data, their windows and spatstat's reference PCFs; README.md there gives source and
// licence) without the io module, so the metrics tests do not depend on it.
#pragma once

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera::test {

inline std::string shared_data_dir() { return TESSERA_SHARED_DATA_DIR; }

// A CSV file with a header line: column names and rows of cells (as text).
struct CsvTable {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;

    int column(const std::string& name) const {
        for (size_t i = 0; i < columns.size(); ++i)
            if (columns[i] == name) return static_cast<int>(i);
        return -1;
    }
    // Numeric cell; "Inf" / "-Inf" / "NA" are read as R writes them.
    double number(size_t row, int col) const {
        const std::string& s = rows.at(row).at(col);
        if (s == "Inf") return INFINITY;
        if (s == "-Inf") return -INFINITY;
        if (s == "NA" || s == "NaN") return NAN;
        return std::stod(s);
    }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) {
        if (!cell.empty() && cell.back() == '\r') cell.pop_back();
        if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = cell.substr(1, cell.size() - 2);
        cells.push_back(cell);
    }
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

inline CsvTable read_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    CsvTable t;
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
    t.columns = split_csv_line(line);
    while (std::getline(in, line)) {
        if (line.empty() || line == "\r") continue;
        t.rows.push_back(split_csv_line(line));
        if (t.rows.back().size() != t.columns.size()) throw std::runtime_error(path + ": ragged row");
    }
    return t;
}

// Names of the point patterns in points/windows.csv, in file order.
inline std::vector<std::string> field_dataset_names() {
    const CsvTable w = read_csv(shared_data_dir() + "/points/windows.csv");
    std::vector<std::string> names;
    for (const auto& row : w.rows) names.push_back(row[w.column("name")]);
    return names;
}

// A field pattern as a 2D exemplar: classes from the "class" column (in order of
// first appearance), else one class "point"; radius from "radius" if present;
// the observation window from points/windows.csv.
inline Exemplar load_field_pattern(const std::string& name) {
    const CsvTable w = read_csv(shared_data_dir() + "/points/windows.csv");
    Exemplar ex;
    ex.dimension = 2;
    bool found = false;
    for (size_t r = 0; r < w.rows.size(); ++r)
        if (w.rows[r][w.column("name")] == name) {
            ex.domain = Domain::box({w.number(r, w.column("xmin")), w.number(r, w.column("ymin")), 0},
                                    {w.number(r, w.column("xmax")), w.number(r, w.column("ymax")), 0}, 2);
            found = true;
        }
    if (!found) throw std::runtime_error("no window for " + name);
    const CsvTable pts = read_csv(shared_data_dir() + "/points/" + name + ".csv");
    const int cx = pts.column("x"), cy = pts.column("y"), cc = pts.column("class"), cr = pts.column("radius");
    for (size_t r = 0; r < pts.rows.size(); ++r) {
        const int type = ex.type_index(cc >= 0 ? pts.rows[r][cc] : std::string("point"));
        ex.add_element(type, {Vec3{pts.number(r, cx), pts.number(r, cy), 0.0}}, cr >= 0 ? pts.number(r, cr) : 0.0);
    }
    return ex;
}

// reference/params.csv: bandwidth (Gaussian sd) and r_max per dataset.
struct ReferenceParams {
    double bandwidth = 0.0, r_max = 0.0;
};
inline ReferenceParams reference_params(const std::string& name) {
    const CsvTable t = read_csv(shared_data_dir() + "/reference/params.csv");
    for (size_t r = 0; r < t.rows.size(); ++r)
        if (t.rows[r][t.column("dataset")] == name)
            return {t.number(r, t.column("bandwidth_sd")), t.number(r, t.column("rmax"))};
    throw std::runtime_error("no reference parameters for " + name);
}

}  // namespace tessera::test
