// The data the quality tests of both methods judge outputs on: the real field patterns of
// tests/data/spatstat in their windows, the examples, and a verbatim 2 x 2 copy of an
// exemplar (what the pair correlation estimator's edge effects alone cost).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "metrics/field_data.hpp"
#include "tessera/tessera.hpp"

namespace tessera::test {

inline Exemplar field_pattern(const std::string& name) {
    const test::CsvTable w = test::read_csv(test::shared_data_dir() + "/points/windows.csv");
    for (size_t r = 0; r < w.rows.size(); ++r)
        if (w.rows[r][w.column("name")] == name) {
            LoadOptions lo;
            lo.input_domain = Domain::box({w.number(r, 1), w.number(r, 2), 0}, {w.number(r, 3), w.number(r, 4), 0}, 2);
            return load(test::shared_data_dir() + "/points/" + name + ".csv", lo);
        }
    throw std::runtime_error("no window for " + name);
}

inline Exemplar example(const std::string& name) { return load(std::string(TESSERA_SOURCE_DIR) + "/examples/" + name + ".json"); }

// The exemplar's elements at 2 x 2 translates of its window: what a verbatim copy scores.
inline Exemplar tiled(const Exemplar& ex) {
    Exemplar out;
    out.dimension = 2;
    out.types = ex.types;
    const Box b = ex.domain.bounds();
    const Vec3 size = b.size();
    out.domain = Domain::box(b.lo, b.lo + Vec3{2 * size.x, 2 * size.y, 0}, 2);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (const Element& e : ex.elements) out.add_element(e.type, {e.position + Vec3{i * size.x, j * size.y, 0}}, e.radius);
    return out;
}

// Every class pair: crowded share within 1.5x of the exemplar's (and at most one element
// more at small counts), no coincident pairs unless the exemplar has them: the bound the
// quality tests put on every method's output.
inline void expect_no_crowding(const Exemplar& ex, const Arrangement& out, const std::string& what) {
    for (const CrowdingPair& c : crowding(ex, out)) {
        EXPECT_LE(c.output_share, 1.5 * c.exemplar_share + 1.0 / std::max<long>(1, c.output_elements))
            << what << " " << c.name_a << ">" << c.name_b;
        if (c.exemplar_coincident == 0) {
            EXPECT_EQ(c.output_coincident, 0) << what << " " << c.name_a << ">" << c.name_b;
        }
    }
}

}  // namespace tessera::test
