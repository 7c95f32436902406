// tessera::TileMaker (tessera/world.hpp): one tile grown next to the final elements of its
// neighbours of earlier phases.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "core/rng.hpp"
#include "tessera/error.hpp"
#include "world/append_element.hpp"
#include "world/pcf_tile_domain.hpp"
#include "tessera/io.hpp"
#include "tessera/option_table.hpp"
#include "tessera/world.hpp"

namespace tessera {

struct TileMaker::Impl {
    Exemplar exemplar;
    WorldOptions options;
    double radius = 0.0;       // the growth's neighbourhood radius r
    double patch_radius = 0.0; // extent of the input patch a tile's growth copies
    double margin = 0.0;       // neighbours' elements within it are locked next to a tile
    double min_tile = 0.0;
    std::string fingerprint;
    std::optional<Grower> indexed;  // method grow: the exemplar indexed once; each tile grows a copy
    std::optional<PcfModel> model;  // method pcf: the exemplar analysed once
};

namespace {

// The farthest sample from its element's centroid (0 for single-sample exemplars).
double element_extent(const Exemplar& x) {
    double extent = 0.0;
    for (const Element& e : x.elements)
        for (int s = 0; s < e.sample_count; ++s) extent = std::max(extent, norm(x.samples[e.first_sample + s].p - e.position));
    return extent;
}

// Distance from p to the box (0 inside); 2D boxes have z from 0 to 0.
double distance_to_box(const Vec3& p, const Box& b) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double d = std::max({b.lo[k] - p[k], 0.0, p[k] - b.hi[k]});
        s += d * d;
    }
    return std::sqrt(s);
}

// The neighbours' elements within the margin of the tile, locked, in the order of the
// neighbours' coordinates and their own order.
Arrangement locked_surroundings(const TileMaker::Impl& m, const TileCoord& tile,
                                const std::vector<NeighbourTile>& neighbours) {
    const int dim = m.exemplar.dimension;
    const std::vector<TileCoord> deps = tile_dependencies(tile, dim);
    std::vector<NeighbourTile> given = neighbours;
    std::sort(given.begin(), given.end(), [](const NeighbourTile& a, const NeighbourTile& b) { return a.coord < b.coord; });
    for (size_t k = 0; k < std::max(given.size(), deps.size()); ++k) {
        if (k >= given.size() || (k < deps.size() && given[k].coord > deps[k]))
            throw Error(ErrorKind::input, "tile " + tile.describe() + ": its neighbour " + deps[k].describe() +
                                              " (an earlier phase) is not given");
        if (k >= deps.size() || given[k].coord != deps[k])
            throw Error(ErrorKind::input, "tile " + tile.describe() + ": " + given[k].coord.describe() +
                                              " is not one of the neighbours it depends on");
        if (!given[k].tile) throw Error(ErrorKind::input, "tile " + given[k].coord.describe() + ": no data");
    }
    const Box box = tile_box(tile, m.options.tile_size, dim);
    Arrangement locked;
    locked.dimension = dim;
    locked.types = m.exemplar.types;
    locked.attribute_names = m.exemplar.attribute_names;
    for (const NeighbourTile& n : given) {
        const Arrangement& t = *n.tile;
        if (t.dimension != dim || t.types.size() != m.exemplar.types.size())
            throw Error(ErrorKind::input, "tile " + n.coord.describe() + ": not a tile of this world's exemplar");
        for (const Element& e : t.elements)
            if (distance_to_box(e.position, box) <= m.margin) world::append_element(t, e, locked, true);
    }
    Vec3 pad{m.margin, m.margin, dim == 3 ? m.margin : 0.0};
    locked.domain = Domain::box(box.lo - pad, box.hi + pad, dim);
    return locked;
}

// The grown elements whose centre lies in the tile, renumbered, in the canonical form.
Arrangement own_elements(const TileMaker::Impl& m, const TileCoord& tile, const Arrangement& grown) {
    const int dim = m.exemplar.dimension;
    Arrangement out;
    out.dimension = dim;
    out.types = m.exemplar.types;
    out.attribute_names = m.exemplar.attribute_names;
    const Box box = tile_box(tile, m.options.tile_size, dim);
    out.domain = Domain::box(box.lo, box.hi, dim);
    // Membership by the centroid of the samples as stored, the centre every reader computes.
    Exemplar made;
    for (const Element& e : grown.elements)
        if (!e.locked) world::append_element(grown, e, made);
    for (const Element& e : made.elements)
        if (tile_at(e.position, m.options.tile_size, dim) == tile) world::append_element(made, e, out);
    // What the neighbours read is what a file holds: the same numbers, bit for bit.
    Arrangement canonical;
    static_cast<Exemplar&>(canonical) = parse_json(tile_to_json(out), "tile " + tile.describe());
    return canonical;
}

// Where a tile without neighbours starts: two or more patches at keyed random places in it,
// a patch diameter apart where the tile has room (dart throwing, a bounded number of throws).
// Growth draws its random choices keyed by world position, so tiles that copy the same input
// patch still grow apart. Several patches rather than one because a front that must cross a
// whole cubic tile from one point ends in more crowded pairs where it closes: spheres_3d over
// 2 x 2 x 2 tiles at 1.2x the smallest size, seeds 1-3, crowded share 0.015-0.017 from
// several patches (exemplar 0.017) against 0.015-0.033 from one.
std::vector<Vec3> seed_centres(const TileMaker::Impl& m, const TileCoord& tile) {
    const int dim = m.exemplar.dimension;
    const Box box = tile_box(tile, m.options.tile_size, dim);
    const double spacing = 2.0 * m.patch_radius;
    const int wanted = std::max(2, static_cast<int>(std::pow(m.options.tile_size / spacing, dim)));
    const core::KeyedRng rng(m.options.grow.seed, core::Purpose::world_seed, static_cast<std::uint64_t>(tile.x),
                             static_cast<std::uint64_t>(tile.y) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(tile.z));
    std::vector<Vec3> centres;
    std::uint64_t counter = 0;
    for (int throws = 0; throws < 30 * wanted && static_cast<int>(centres.size()) < wanted; ++throws) {
        Vec3 p = box.lo;
        for (int k = 0; k < dim; ++k) p[k] += rng.uniform(counter++) * m.options.tile_size;
        const bool apart = std::all_of(centres.begin(), centres.end(), [&](const Vec3& q) { return norm(p - q) >= spacing; });
        if (apart) centres.push_back(p);
    }
    return centres;
}

// Rounded up at 4 significant digits: a tile size that is enough.
std::string short_number(double v) {
    char text[32];
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 3);
    std::snprintf(text, sizeof text, "%.4g", std::ceil(v / scale) * scale);
    return text;
}

std::string describe_options(const WorldOptions& o) {
    std::string text = "tile_size=" + format_option_value(o.tile_size);
    if (o.method == WorldMethod::pcf) {
        text += ";method=pcf;seed=" + std::to_string(o.grow.seed);
        for (const auto& spec : pcf_option_table())
            if (spec.name != "threads" && spec.name != "seed") text += ";" + spec.name + "=" + format_option_value(spec.get(o.pcf));
        return text;
    }
    for (const auto& spec : grow_option_table())
        if (spec.name != "threads") text += ";" + spec.name + "=" + format_option_value(spec.get(o.grow));
    return text;
}

// The PCF method's reach: pairs further apart than the end of the PCF axis (extent plus a
// kernel width, in r_max, beyond contact for disks) do not count, so neighbours' elements
// beyond it do not change a tile.
double pcf_reach(const PcfModel& model) {
    double largest = 0.0;
    for (const auto& radii : model.radii)
        if (!radii.empty()) largest = std::max(largest, radii.front());
    return model.r_max * (model.settings.extent + 2.0 * model.settings.sigma) + 2.0 * largest;
}

// The seed of one tile's PCF synthesis: the world's seed and the tile's coordinates.
std::uint64_t tile_seed(std::uint64_t seed, const TileCoord& t) {
    const core::KeyedRng rng(seed, core::Purpose::world_seed, static_cast<std::uint64_t>(t.x) ^ 0x5bd1e995ull,
                             static_cast<std::uint64_t>(t.y) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(t.z));
    return rng.bits(0);
}

// Method pcf: the tile synthesized next to its neighbours' elements within the margin, in
// the tile and the neighbours' strips (pcf_tile_domain.hpp), new elements starting in the
// tile.
Arrangement pcf_tile(const TileMaker::Impl& m, const TileCoord& tile, const Arrangement& locked,
                     const Progress& progress) {
    const Domain domain = world::pcf_tile_domain(tile, m.options.tile_size, m.margin);
    Exemplar fixed = locked;
    fixed.elements.clear();
    for (const Element& e : locked.elements)
        if (domain.inside(e.position)) world::append_element(locked, e, fixed, true);
    const Box box = tile_box(tile, m.options.tile_size, 2);
    PcfSynthOptions o = m.options.pcf;
    o.seed = tile_seed(m.options.grow.seed, tile);
    return synthesize_pcf_next_to(m.exemplar, *m.model, domain, fixed, Domain::box(box.lo, box.hi, 2), o, progress);
}

}  // namespace

TileMaker::TileMaker(const Exemplar& exemplar, const WorldOptions& options) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    if (!(options.tile_size > 0.0) || !std::isfinite(options.tile_size))
        throw Error(ErrorKind::option, "tile_size: must be a number > 0, got " + format_option_value(options.tile_size));
    m.exemplar = exemplar;
    m.options = options;
    if (options.method == WorldMethod::pcf) {
        if (exemplar.dimension != 2)
            throw Error(ErrorKind::option, "method: the PCF method makes 2D worlds; this exemplar is 3D (use grow)");
        check_options(pcf_option_table(), options.pcf);
        m.model = analyze_distribution(exemplar, options.pcf.analysis, options.pcf.threads);
        m.margin = pcf_reach(*m.model);
    } else {
        m.indexed.emplace(exemplar, options.grow);  // validates the exemplar and the growth options
        m.radius = m.indexed->radius();
        const double patch = options.grow.choice == GrowChoice::patch ? options.grow.patch_extent : 1.0;
        m.patch_radius = patch * m.radius;
        m.margin = m.patch_radius + m.radius + 2.0 * element_extent(exemplar);
    }
    m.min_tile = m.margin;
    if (options.tile_size < m.min_tile)
        throw Error(ErrorKind::option, "tile_size: " + format_option_value(options.tile_size) +
                                           " is smaller than the neighbourhood it must hold (" +
                                           short_number(m.min_tile) + " for this exemplar)");
    // The phase order is part of what a tile is made from: a cache of 3D tiles made in
    // another order (binary, before the Gray order) belongs to another world.
    m.fingerprint = to_json(exemplar) + "\n" + describe_options(options) +
                    (exemplar.dimension == 3 ? "\nphases: gray code order" : "");
}

TileMaker::~TileMaker() = default;
TileMaker::TileMaker(TileMaker&&) noexcept = default;
TileMaker& TileMaker::operator=(TileMaker&&) noexcept = default;

double TileMaker::margin() const { return impl_->margin; }
double TileMaker::min_tile_size() const { return impl_->min_tile; }
int TileMaker::dimension() const { return impl_->exemplar.dimension; }
const Exemplar& TileMaker::exemplar() const { return impl_->exemplar; }
const WorldOptions& TileMaker::options() const { return impl_->options; }
const std::string& TileMaker::fingerprint() const { return impl_->fingerprint; }

Arrangement TileMaker::make(const TileCoord& tile, const std::vector<NeighbourTile>& neighbours,
                            const Progress& progress) const {
    const Impl& m = *impl_;
    const int dim = m.exemplar.dimension;
    if (dim == 2 && tile.z != 0)
        throw Error(ErrorKind::input, "tile " + tile.describe() + ": a 2D world's tiles have z = 0");
    const Arrangement locked = locked_surroundings(m, tile, neighbours);
    if (m.model) return own_elements(m, tile, pcf_tile(m, tile, locked, progress));
    Grower grower(*m.indexed);
    if (locked.elements.empty())
        grower.seed(seed_centres(m, tile));
    else
        grower.set_arrangement(locked);
    if (progress) grower.set_progress(progress);
    const Box box = tile_box(tile, m.options.tile_size, dim);
    grower.grow(Domain::box(box.lo, box.hi, dim), RegionEdge::open);
    return own_elements(m, tile, grower.arrangement());
}

}  // namespace tessera
