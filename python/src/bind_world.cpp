// Worlds for Python (tessera/world.hpp): TileMaker, the streaming World and the tile helpers.
// Tiles cross the boundary in their compact form (tile_arrays.hpp), which pickles, so a
// distributed build (python/tessera/world.py) ships tiles between processes as numpy arrays;
// tile coordinates are tuples (x, y) in 2D and (x, y, z) in 3D. As for Grower, options arrive
// as a dict keyed by the Python keyword names (checked by the growth's option table) and the
// GIL is released while a tile is made.
//
// TileMaker::make is thread-safe, so a TileMaker may serve several Python threads at once. A
// World is not: every World method checks, with the GIL held, that no call is under way on
// another thread.
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_table.hpp"
#include "option_values.hpp"
#include "tessera/io.hpp"
#include "tessera/world.hpp"
#include "tile_arrays.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

// ---- coordinates ------------------------------------------------------------------------

// (x, y) or (x, y, z) of integers; a 2D world takes (x, y) (or z = 0, which the library checks).
tessera::TileCoord coord_of(const py::handle& value, int dimension, const std::string& what) {
    const std::string form = dimension == 2 ? "(x, y)" : "(x, y, z)";
    const auto fail = [&] { bad(what + " must be a tile coordinate " + form + " of integers, got " + std::string(py::repr(value))); };
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) fail();
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 3 && (dimension == 3 || seq.size() != 2)) fail();
    std::int64_t c[3] = {0, 0, 0};
    for (std::size_t k = 0; k < seq.size(); ++k) {
        const py::object item = seq[k];
        if (py::isinstance<py::bool_>(item) || py::isinstance<py::float_>(item) || !py::hasattr(item, "__index__")) fail();
        try {
            c[k] = py::reinterpret_steal<py::int_>(PyNumber_Index(item.ptr())).cast<std::int64_t>();
        } catch (const py::cast_error&) {
            fail();
        }
    }
    return {c[0], c[1], c[2]};
}

py::tuple coord_tuple(const tessera::TileCoord& c, int dimension) {
    return dimension == 2 ? py::make_tuple(c.x, c.y) : py::make_tuple(c.x, c.y, c.z);
}

py::list coord_list(const std::vector<tessera::TileCoord>& coords, int dimension) {
    py::list out;
    for (const tessera::TileCoord& c : coords) out.append(coord_tuple(c, dimension));
    return out;
}

// The finished neighbours given to make(): {coord: tile} or a sequence of (coord, tile) pairs.
struct Neighbours {
    std::vector<tessera::Arrangement> tiles;
    std::vector<tessera::NeighbourTile> refs;  // into `tiles`, filled once all are read
};

Neighbours neighbours_of(const py::handle& given, int dimension) {
    const char* form = "neighbours must be a dict {coord: tile} or a sequence of (coord, tile) pairs";
    std::vector<std::pair<py::handle, py::handle>> pairs;
    if (py::isinstance<py::dict>(given)) {
        for (const auto& item : py::reinterpret_borrow<py::dict>(given)) pairs.emplace_back(item.first, item.second);
    } else if (!given.is_none()) {
        if (!py::isinstance<py::sequence>(given) || py::isinstance<py::str>(given)) bad(form);
        for (const py::handle item : given) {
            if (!py::isinstance<py::sequence>(item) || py::len(item) != 2) bad(form);
            pairs.emplace_back(item[py::int_(0)], item[py::int_(1)]);
        }
    }
    Neighbours out;
    std::vector<tessera::TileCoord> coords;
    for (const auto& [coord, tile] : pairs) {
        coords.push_back(coord_of(coord, dimension, "a neighbour's coordinate"));
        out.tiles.push_back(tile_from_compact(tile, "neighbour " + coords.back().describe()));
    }
    for (std::size_t i = 0; i < coords.size(); ++i) out.refs.push_back({coords[i], &out.tiles[i]});
    return out;
}

// ---- options ----------------------------------------------------------------------------

tessera::WorldOptions world_options(const tessera::Exemplar& exemplar, const py::handle& tile_size,
                                    const py::dict& options, const std::string& owner) {
    if (py::isinstance<py::bool_>(tile_size) || py::isinstance<py::str>(tile_size))
        bad("tile_size must be a number, got " + std::string(py::repr(tile_size)));
    tessera::WorldOptions o;
    o.tile_size = number(tile_size, "tile_size");
    // "method" picks the table the other keywords belong to (tessera.world checked that
    // none of the other method's is set).
    std::string method = "grow";
    py::dict rest;
    for (const auto& [key, value] : options) {
        if (py::str(key).cast<std::string>() != "method")
            rest[key] = value;
        else if (!value.is_none())
            method = py::str(value);
    }
    if (method == "pcf") {
        o.method = tessera::WorldMethod::pcf;
        apply_keywords(tessera::pcf_option_table(), o.pcf, rest, exemplar.dimension, owner + " method 'pcf'");
        o.grow.seed = o.pcf.seed;  // a world's seed is WorldOptions::grow.seed (tessera/world.hpp)
    } else if (method == "grow") {
        apply_keywords(tessera::grow_option_table(), o.grow, rest, exemplar.dimension, owner);
    } else {
        bad("method must be 'grow' or 'pcf', got '" + method + "'");
    }
    return o;
}

std::unique_ptr<tessera::TileMaker> make_maker(const tessera::Exemplar& exemplar, const py::handle& tile_size,
                                               const py::dict& options) {
    const tessera::WorldOptions o = world_options(exemplar, tile_size, options, "TileMaker");
    py::gil_scoped_release release;  // indexing the exemplar takes a while
    return std::make_unique<tessera::TileMaker>(exemplar, o);
}

py::dict make_tile(const tessera::TileMaker& maker, const py::handle& coord, const py::handle& neighbours) {
    const tessera::TileCoord c = coord_of(coord, maker.dimension(), "coord");
    const Neighbours given = neighbours_of(neighbours, maker.dimension());
    tessera::Arrangement tile;
    {
        py::gil_scoped_release release;
        tile = maker.make(c, given.refs);
    }
    return compact_tile(tile);
}

// ---- the streaming world ----------------------------------------------------------------

struct PyWorld {
    explicit PyWorld(tessera::World w) : world(std::move(w)) {}
    tessera::World world;
    bool busy = false;  // read and written with the GIL held only
};

// Marks the world busy for one call; the GIL is held on entry and exit.
class Using {
public:
    explicit Using(PyWorld& w) : w_(w) {
        if (w_.busy) throw std::runtime_error("this World is in use by another thread (a World serves one thread at a time)");
        w_.busy = true;
    }
    ~Using() { w_.busy = false; }
    Using(const Using&) = delete;
    Using& operator=(const Using&) = delete;

private:
    PyWorld& w_;
};

std::unique_ptr<PyWorld> make_world(const tessera::Exemplar& exemplar, const py::handle& tile_size,
                                    const std::optional<std::string>& cache_dir, const py::dict& options) {
    const tessera::WorldOptions o = world_options(exemplar, tile_size, options, "World");
    py::gil_scoped_release release;
    return std::make_unique<PyWorld>(tessera::World(exemplar, o, cache_dir.value_or("")));
}

py::dict world_tile(PyWorld& w, const py::handle& coord) {
    const Using in_use(w);
    const tessera::TileCoord c = coord_of(coord, w.world.maker().dimension(), "coord");
    const tessera::Arrangement* tile = nullptr;
    {
        py::gil_scoped_release release;
        tile = &w.world.tile(c);  // a node of the world's map: stays put
    }
    return compact_tile(*tile);
}

tessera::Arrangement world_around(PyWorld& w, const py::handle& point, double radius) {
    const Using in_use(w);
    const tessera::Vec3 p = to_vec3(point, "point");
    py::gil_scoped_release release;
    return w.world.around(p, radius);
}

py::list world_tiles_around(PyWorld& w, const py::handle& point, double radius) {
    const Using in_use(w);
    return coord_list(w.world.tiles_around(to_vec3(point, "point"), radius), w.world.maker().dimension());
}

// ---- tiles as data ----------------------------------------------------------------------

tessera::Arrangement merge(const py::sequence& compacts) {
    std::vector<tessera::Arrangement> tiles;
    for (std::size_t i = 0; i < compacts.size(); ++i)
        tiles.push_back(tile_from_compact(compacts[i], "tiles[" + std::to_string(i) + "]"));
    if (tiles.empty()) bad("tiles: nothing to merge (give at least one tile)");
    std::vector<const tessera::Arrangement*> parts;
    for (const tessera::Arrangement& t : tiles) {
        if (t.dimension != tiles.front().dimension) bad("tiles: 2D and 3D tiles cannot be merged");
        parts.push_back(&t);
    }
    py::gil_scoped_release release;
    return tessera::merge_tiles(parts, tiles.front().dimension);
}

py::list closure(const py::iterable& wanted, int dimension) {
    if (dimension != 2 && dimension != 3) bad("dimension must be 2 or 3, got " + std::to_string(dimension));
    std::vector<tessera::TileCoord> coords;
    for (const py::handle c : wanted) coords.push_back(coord_of(c, dimension, "a tile of `wanted`"));
    return coord_list(tessera::tile_closure(coords, dimension), dimension);
}

void bind_tile_maker(py::module_& m) {
    py::class_<tessera::TileMaker>(m, "TileMaker",
                                   "Makes the tiles of one world (use tessera.world.TileMaker, which wraps this class).")
        .def(py::init(&make_maker), py::arg("exemplar"), py::arg("tile_size"), py::arg("options"))
        .def("make", &make_tile, py::arg("coord"), py::arg("neighbours") = py::none(),
             "The tile `coord` (compact form) next to `neighbours`, the finished tiles of dependencies(coord).")
        .def(
            "dependencies",
            [](const tessera::TileMaker& t, const py::handle& c) {
                return coord_list(tessera::tile_dependencies(coord_of(c, t.dimension(), "coord"), t.dimension()), t.dimension());
            },
            py::arg("coord"), "The neighbours of earlier phases the tile is grown next to, in coordinate order.")
        .def(
            "phase",
            [](const tessera::TileMaker& t, const py::handle& c) { return tessera::tile_phase(coord_of(c, t.dimension(), "coord"), t.dimension()); },
            py::arg("coord"), "The tile's phase: (x mod 2) + 2 (y mod 2) in 2D; in 3D the parities in Gray-code order (docs/worlds.md).")
        .def_property_readonly("phases", [](const tessera::TileMaker& t) { return tessera::tile_phases(t.dimension()); })
        .def_property_readonly("margin", &tessera::TileMaker::margin)
        .def_property_readonly("min_tile_size", &tessera::TileMaker::min_tile_size)
        .def_property_readonly("dimension", &tessera::TileMaker::dimension)
        .def_property_readonly("tile_size", [](const tessera::TileMaker& t) { return t.options().tile_size; })
        .def_property_readonly("fingerprint", &tessera::TileMaker::fingerprint);
}

void bind_streaming_world(py::module_& m) {
    py::class_<PyWorld>(m, "World", "Tiles answered on demand (use tessera.world.World, which wraps this class).")
        .def(py::init(&make_world), py::arg("exemplar"), py::arg("tile_size"), py::arg("cache_dir"), py::arg("options"))
        .def("tile", &world_tile, py::arg("coord"), "The finished tile (compact form), made with its dependencies when not yet known.")
        .def("tiles_around", &world_tiles_around, py::arg("point"), py::arg("radius"),
             "The tiles whose box comes within `radius` of `point`, in coordinate order.")
        .def("around", &world_around, py::arg("point"), py::arg("radius"), "Those tiles, finished, merged into one Arrangement.")
        .def_property_readonly("made", [](PyWorld& w) { const Using in_use(w); return w.world.made(); })
        .def_property_readonly("known", [](PyWorld& w) { const Using in_use(w); return w.world.known(); })
        .def_property_readonly("fingerprint", [](PyWorld& w) { const Using in_use(w); return w.world.maker().fingerprint(); });
}

void bind_tile_functions(py::module_& m) {
    m.def("tile_to_compact", &compact_tile, py::arg("tile"), "The compact form of an arrangement with a box domain.");
    m.def(
        "tile_from_compact", [](const py::handle& c) { return tile_from_compact(c, "tile"); }, py::arg("tile"));
    m.def("tile_json", [](const tessera::Arrangement& t) { return tessera::tile_to_json(t); }, py::arg("tile"));
    m.def("tile_json", [](const py::dict& c) { return tessera::tile_to_json(tile_from_compact(c, "tile")); }, py::arg("tile"));
    m.def("tile_hash", [](const tessera::Arrangement& t) { return tessera::tile_hash(t); }, py::arg("tile"));
    m.def("tile_hash", [](const py::dict& c) { return tessera::tile_hash(tile_from_compact(c, "tile")); }, py::arg("tile"));
    m.def("merge_tiles", &merge, py::arg("tiles"));
    m.def("tile_closure", &closure, py::arg("wanted"), py::arg("dimension"));
    // How an exemplar travels to the workers of a distributed build: its native JSON text.
    m.def("exemplar_to_json", [](const tessera::Exemplar& e) { return tessera::to_json(e); }, py::arg("exemplar"));
    m.def("exemplar_from_json", &tessera::parse_json, py::arg("text"), py::arg("source"));
}

}  // namespace

void bind_world(py::module_& m) {
    bind_tile_maker(m);
    bind_streaming_world(m);
    bind_tile_functions(m);
}

}  // namespace tessera_python
