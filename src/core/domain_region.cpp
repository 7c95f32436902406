// Domain::region — the part of a domain where a predicate holds, as a grid of cells. A brush
// stroke's band (brush.hpp) is such a region: growth fills it like any other domain.
#include <cmath>

#include "core/domain_shape.hpp"
#include "tessera/domain.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

class RegionShape : public VoxelShape {
public:
    std::string name;
    std::string describe() const override { return "region " + name; }
};

constexpr double kMaxCells = 16777216.0;  // 2^24: a 4096^2 image or a 256^3 volume

}  // namespace

Domain Domain::region(const Domain& within, const std::function<bool(const Vec3&)>& keep, double cell,
                      const std::string& name) {
    const int dim = within.dimension();
    if (!(cell > 0.0) || !std::isfinite(cell)) throw Error(ErrorKind::domain, name + ": the cell size must be > 0");
    const Box b = within.bounds();
    const Vec3 size = b.size();
    int n[3] = {1, 1, 1};
    double cells = 1.0;
    for (int a = 0; a < dim; ++a) {
        n[a] = std::max(1, static_cast<int>(std::ceil(size[a] / cell)));
        cells *= n[a];
    }
    if (cells > kMaxCells)
        throw Error(ErrorKind::domain, name + ": " + std::to_string(static_cast<long long>(cells)) +
                                           " cells of size " + std::to_string(cell) + " are too many (at most 2^24)");
    auto shape = std::make_shared<RegionShape>();
    shape->name = name;
    shape->dimension = dim;
    shape->bounds = b;
    for (int a = 0; a < 3; ++a) shape->n[a] = n[a];
    shape->spacing = {size.x / n[0], size.y / n[1], dim == 3 ? size.z / n[2] : 1.0};
    shape->first = b.lo + Vec3(0.5 * shape->spacing.x, 0.5 * shape->spacing.y, dim == 3 ? 0.5 * shape->spacing.z : 0.0);
    shape->threshold = 0.5;
    shape->values.assign(static_cast<size_t>(shape->cell_count()), 0.0f);
    for (int64_t v = 0; v < shape->cell_count(); ++v) {
        const Vec3 c = shape->centre(v);
        shape->values[static_cast<size_t>(v)] = within.inside(c) && keep(c) ? 1.0f : 0.0f;
    }
    if (shape->finish(0) == 0) throw Error(ErrorKind::domain, name + " is empty: no cell of the domain is in it");
    return from_shape(std::move(shape), dim == 2 ? Kind::mask : Kind::mesh);
}

}  // namespace tessera
