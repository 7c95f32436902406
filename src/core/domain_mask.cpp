// core/domain_mask.cpp — the 2D grayscale image mask domain (Domain::mask): a PNG
// (or in-memory gray pixels) stretched over a box, white = inside. The image is a
// VoxelShape with one cell per pixel, so c(p) of Eq. 6 is the bilinear gray level,
// which gives the search a smooth boundary term where the mask is anti-aliased.
#include <stb_image.h>

#include <filesystem>
#include <sstream>

#include "core/domain_shape.hpp"
#include "tessera/error.hpp"

namespace tessera {
namespace {

class MaskShape final : public VoxelShape {
public:
    std::string name;
    std::string describe() const override {
        std::ostringstream s;
        s << "mask " << name << " (" << n[0] << "x" << n[1] << " pixels, threshold " << threshold << ") on ["
          << bounds.lo.x << "," << bounds.hi.x << "]x[" << bounds.lo.y << "," << bounds.hi.y << "]";
        return s.str();
    }
};

}  // namespace

Domain Domain::mask(const GrayImage& image, const Vec3& lo, const Vec3& hi, double threshold, const std::string& name) {
    const Domain box = Domain::box(lo, hi, 2);  // validates the box
    if (image.width < 1 || image.height < 1 || image.values.size() != size_t(image.width) * image.height)
        throw Error(ErrorKind::domain, "mask " + name + ": the image has no pixels");
    if (!(threshold > 0.0 && threshold <= 1.0))
        throw Error(ErrorKind::domain, "mask " + name + ": threshold must be in (0, 1], got " + std::to_string(threshold));
    auto shape = std::make_shared<MaskShape>();
    shape->name = std::filesystem::path(name).filename().string();
    shape->dimension = 2;
    shape->bounds = box.bounds();
    shape->n[0] = image.width;
    shape->n[1] = image.height;
    const Vec3 size = shape->bounds.size();
    shape->spacing = {size.x / image.width, size.y / image.height, 1.0};
    shape->first = shape->bounds.lo + Vec3(shape->spacing.x * 0.5, shape->spacing.y * 0.5, 0.0);
    shape->threshold = threshold;
    shape->values.resize(image.values.size());
    // Image rows run top to bottom; grid rows bottom to top (y up).
    for (int r = 0; r < image.height; ++r)
        for (int i = 0; i < image.width; ++i)
            shape->values[shape->index(i, image.height - 1 - r, 0)] = image.values[size_t(r) * image.width + i];
    if (shape->finish(0) == 0)
        throw Error(ErrorKind::domain, "mask " + name + " is empty: no pixel reaches the threshold " +
                                           std::to_string(threshold) + " (white = inside)");
    shape->source.file = name;
    shape->source.box = shape->bounds;
    shape->source.threshold = threshold;
    return from_shape(std::move(shape), Kind::mask);
}

Domain Domain::mask(const std::string& png_path, const Vec3& lo, const Vec3& hi, double threshold) {
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(png_path.c_str(), &w, &h, &channels, 1);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw Error(ErrorKind::io, png_path + ": cannot read the mask image (" + (reason ? reason : "unknown error") + ")");
    }
    GrayImage image;
    image.width = w;
    image.height = h;
    image.values.resize(size_t(w) * h);
    for (size_t i = 0; i < image.values.size(); ++i) image.values[i] = pixels[i] / 255.0f;
    stbi_image_free(pixels);
    return mask(image, lo, hi, threshold, png_path);
}

}  // namespace tessera
