// The real point patterns (tests/data/spatstat/points) for the benchmarks: their names and
// observation windows.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tessera_bench {

// The window "xmin,ymin,xmax,ymax" of dataset `name` from points/windows.csv
// (name,xmin,ymin,xmax,ymax,...); empty when it is not listed.
inline std::string window_of(const std::string& shared, const std::string& name) {
    std::ifstream in(shared + "/points/windows.csv");
    std::string line;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string field;
        std::getline(s, field, ',');
        if (field != name) continue;
        std::string box, v;
        for (int k = 0; k < 4 && std::getline(s, v, ','); ++k) box += (k ? "," : "") + v;
        return box;
    }
    return "";
}

// Every dataset listed in points/windows.csv, in file order.
inline std::vector<std::string> shared_datasets(const std::string& shared) {
    std::ifstream in(shared + "/points/windows.csv");
    std::vector<std::string> names;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line))
        if (const auto comma = line.find(','); comma != std::string::npos && comma > 0)
            names.push_back(line.substr(0, comma));
    return names;
}

}  // namespace tessera_bench
