// Tests of the PCF model pictures (tessera/pcf_plot.hpp): one titled panel per PCF in SVG
// and PNG, the measured overlay, class names outside ASCII, and option errors.
#include <gtest/gtest.h>

#include <stb_image.h>

#include "analysis_test_data.hpp"
#include "temp_dir.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_plot.hpp"

using namespace tessera;

namespace {

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(PcfPlot, OnePanelPerPcf) {
    const PcfModel m = analyze_distribution(test::three_classes());
    const std::string svg = pcf_plot_svg(m);
    EXPECT_EQ(count(svg, "<polygon"), 6);   // envelopes
    EXPECT_EQ(count(svg, "<polyline"), 6);  // means
    for (const char* title : {">a<", ">b<", ">c<", ">b | a<", ">c | a<", ">c | b<"})
        EXPECT_EQ(count(svg, title), 1) << title;
    // 6 panels: 3 columns, 2 rows of the default panel size, plus the notes.
    EXPECT_NE(svg.find("width=\"900\""), std::string::npos);

    const std::string png = pcf_plot_png(m);
    int w = 0, h = 0, channels = 0;
    ASSERT_TRUE(stbi_info_from_memory(reinterpret_cast<const unsigned char*>(png.data()), static_cast<int>(png.size()),
                                      &w, &h, &channels));
    EXPECT_EQ(w, 900);
    EXPECT_GT(h, 400);
}

TEST(PcfPlot, MeasuredOverlayAndOptions) {
    const Exemplar ex = test::three_classes();
    const PcfModel m = analyze_distribution(ex);
    PcfPlotOptions o;
    o.measured = measure_distribution(m, test::three_classes());
    o.columns = 2;
    o.panel_width = 200;
    o.panel_height = 150;
    const std::string svg = pcf_plot_svg(m, o);
    EXPECT_EQ(count(svg, "<polyline"), 12);
    EXPECT_NE(svg.find("width=\"400\""), std::string::npos);
    EXPECT_NE(svg.find("measured"), std::string::npos);
    EXPECT_FALSE(pcf_plot_png(m, o).empty());

    o.measured.pop_back();
    EXPECT_THROW(pcf_plot_svg(m, o), Error);
    PcfPlotOptions tiny;
    tiny.panel_width = 10;
    EXPECT_THROW(pcf_plot_png(m, tiny), Error);
}

TEST(PcfPlot, NamesAreEscapedAndNonAsciiIsSafe) {
    Exemplar ex = test::three_classes();
    ex.types[0].name = "a<b&c";
    ex.types[1].name = "\xc3\xa9t\xc3\xa9";  // "été" in UTF-8
    const PcfModel m = analyze_distribution(ex);
    const std::string svg = pcf_plot_svg(m);
    EXPECT_NE(svg.find(">a&lt;b&amp;c<"), std::string::npos);
    EXPECT_FALSE(pcf_plot_png(m).empty());
}

class PcfPlotFile : public test::TempDirTest {};

TEST_F(PcfPlotFile, WritesByExtension) {
    const PcfModel m = analyze_distribution(test::poisson_points(40, 4.0, 1));
    write_pcf_plot(m, path("p.SVG"));
    EXPECT_EQ(read("p.SVG").rfind("<?xml", 0), 0u);
    write_pcf_plot(m, path("p.png"));
    EXPECT_EQ(read("p.png").compare(0, 4, "\x89PNG"), 0);
    try {
        write_pcf_plot(m, path("p.jpg"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find(".jpg"), std::string::npos);
    }
}
