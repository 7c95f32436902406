// The PCF method's fidelity on the real field data of tests/data/spatstat at 4x the area:
// the pair correlation error (metrics' pcf_relative_error, every class pair, from r = h)
// within 2x of what a verbatim 2 x 2 copy of the exemplar scores (docs/pcf_synthesis.md,
// "Relaxation").
#include <gtest/gtest.h>

#include <string>

#include "quality_data.hpp"

using namespace tessera;

TEST(PcfQuality, FieldDataAtFourTimesTheAreaKeepTheirPairCorrelation) {
    for (const std::string& name : test::field_dataset_names()) {
        const Exemplar ex = test::field_pattern(name);
        PcfSynthOptions o;
        o.threads = 2;
        o.seed = 1;
        const Arrangement out = synthesize_pcf(ex, ex.domain.scaled(2.0), o);
        const double error = pcf_relative_error(ex, out), reference = pcf_relative_error(ex, test::tiled(ex));
        EXPECT_LT(error, 2.0 * reference) << name << ": PCF error " << error << ", a 2 x 2 copy scores " << reference;
    }
}
