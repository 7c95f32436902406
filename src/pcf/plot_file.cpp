// write_pcf_plot: the PCF model picture by file extension, written atomically like
// every other output of tessera (a failed run leaves no partial file).
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/pcf_plot.hpp"

namespace tessera {

void write_pcf_plot(const PcfModel& model, const std::string& path, const PcfPlotOptions& options) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".svg")
        write_file_atomic(path, pcf_plot_svg(model, options));
    else if (extension == ".png")
        write_file_atomic(path, pcf_plot_png(model, options));
    else
        throw Error(ErrorKind::option, "PCF plot " + path + ": unsupported extension '" + extension +
                                           "' (supported: .svg, .png)");
}

}  // namespace tessera
