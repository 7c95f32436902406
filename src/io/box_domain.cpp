// io/box_domain.cpp — parse_box_domain: the "xmin,ymin,xmax,ymax[,zmin,zmax]" text
// that options such as --input-domain and --domain take. Lives in io because it
// is text parsing; every failure is Error(option) naming the parameter, since the
// text comes from a user's option, not from a data file.
#include <string>
#include <vector>

#include "io/io_util.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera {

using namespace io_detail;

Domain parse_box_domain(const std::string& text, const std::string& parameter) {
    const auto fail = [&](const std::string& what) {
        throw Error(ErrorKind::option, parameter + ": " + what);
    };
    const std::string usage = "expected xmin,ymin,xmax,ymax (2D) or xmin,ymin,xmax,ymax,zmin,zmax (3D)";
    std::vector<double> values;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        const std::string_view field = std::string_view(text).substr(
            start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto value = parse_number(field);
        if (!value) fail("'" + std::string(trim(field)) + "' is not a number in '" + text + "'; " + usage);
        values.push_back(*value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (values.size() != 4 && values.size() != 6)
        fail(usage + ", got " + std::to_string(values.size()) + " values in '" + text + "'");
    const bool three_d = values.size() == 6;
    const Vec3 lo{values[0], values[1], three_d ? values[4] : 0.0};
    const Vec3 hi{values[2], values[3], three_d ? values[5] : 0.0};
    try {
        return Domain::box(lo, hi, three_d ? 3 : 2);
    } catch (const Error& e) {
        fail(std::string(e.what()) + " in '" + text + "'");
    }
    return {};  // not reached: fail() throws
}

}  // namespace tessera
