// The analysed model as JSON (`tessera analyze -o model.json`, docs/pcf.md) and back.
// The reader is strict like the exemplar reader (src/io/json_format.cpp): unknown keys,
// missing keys, wrong types and values that break the model's invariants (a cycle, a PCF
// of the wrong length, an order that puts a class before its parent) are errors naming
// the source and the key, because a synthesis from a silently repaired model would not
// be the synthesis the user asked for. Doubles are written in the shortest form that
// reads back exactly, so a save + load gives an identical model.
#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>

#include "pcf/dependency_graph.hpp"
#include "pcf/pcf_estimate.hpp"
#include "pcf/pcf_math.hpp"
#include "pcf/sparse_classes.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr const char* model_format = "tessera-pcf-model";
constexpr int model_version = 3;

class ModelReader {
public:
    explicit ModelReader(const std::string& source) : source_(source) {}

    PcfModel read(const std::string& text) {
        Json doc;
        try {
            doc = Json::parse(text);
        } catch (const Json::exception& e) {
            std::string message = e.what();
            const size_t tag_end = message.find("] ");
            if (message.rfind("[json.exception", 0) == 0 && tag_end != std::string::npos)
                message = message.substr(tag_end + 2);
            fail("", "invalid JSON: " + message);
        }
        object(doc, "");
        const Json& format = require(doc, "format", "");
        if (!format.is_string() || format.get<std::string>() != model_format)
            fail("format", std::string("must be \"") + model_format + "\", got " + format.dump());
        const Json& version = require(doc, "version", "");
        if (!version.is_number_integer() || version.get<long long>() < 1 || version.get<long long>() > model_version)
            fail("version", "unsupported version " + version.dump() + " (this build reads versions 1 to " +
                                std::to_string(model_version) + ")");
        // Version 1 had no separations, version 2 no sparse classes (models analysed
        // before them synthesize without).
        const bool separations = version.get<long long>() >= 2;
        const bool sparse = version.get<long long>() >= 3;
        if (sparse)
            keys(doc, {"format", "version", "settings", "r_max", "area", "classes", "order", "x", "pcfs", "separations",
                       "sparse"}, "");
        else if (separations)
            keys(doc, {"format", "version", "settings", "r_max", "area", "classes", "order", "x", "pcfs", "separations"}, "");
        else
            keys(doc, {"format", "version", "settings", "r_max", "area", "classes", "order", "x", "pcfs"}, "");
        PcfModel m;
        read_settings(require(doc, "settings", ""), m.settings);
        m.r_max = positive(require(doc, "r_max", ""), "r_max");
        m.area = positive(require(doc, "area", ""), "area");
        read_classes(require(doc, "classes", ""), m);
        read_order(require(doc, "order", ""), m);
        read_axis(require(doc, "x", ""), m);
        read_pcfs(require(doc, "pcfs", ""), m);
        if (separations) read_separations(require(doc, "separations", ""), m);
        if (sparse) read_sparse(require(doc, "sparse", ""), m);
        for (size_t c = 0; c < m.classes.size(); ++c)
            if (m.counts[c] < kPcfSparseCount && !pcf::sparse_class(m, static_cast<int>(c)))
                fail("sparse", "class '" + m.classes[c] + "' has " + std::to_string(m.counts[c]) +
                                   " elements: it needs an entry (fewer than " + std::to_string(kPcfSparseCount) + ")");
        return m;
    }

private:
    std::string source_;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(ErrorKind::input, source_ + ": " + (where.empty() ? what : where + ": " + what));
    }
    static std::string at(const std::string& where, const std::string& key) {
        return where.empty() ? key : where + "." + key;
    }
    static std::string at(const std::string& where, size_t index) {
        return where + "[" + std::to_string(index) + "]";
    }
    void object(const Json& v, const std::string& where) const {
        if (!v.is_object()) fail(where, where.empty() ? "the document must be a JSON object" : "must be an object");
    }
    void keys(const Json& v, std::initializer_list<const char*> allowed, const std::string& where) const {
        for (const auto& item : v.items())
            if (std::none_of(allowed.begin(), allowed.end(), [&](const char* k) { return item.key() == k; }))
                fail(where, "unknown key '" + item.key() + "'");
        for (const char* k : allowed)
            if (!v.contains(k)) fail(where, std::string("missing \"") + k + "\"");
    }
    const Json& require(const Json& v, const char* key, const std::string& where) const {
        const auto it = v.find(key);
        if (it == v.end()) fail(where, std::string("missing \"") + key + "\"");
        return *it;
    }
    double number(const Json& v, const std::string& where) const {
        if (!v.is_number()) fail(where, "must be a number, got " + v.dump());
        const double x = v.get<double>();
        if (!std::isfinite(x)) fail(where, "is NaN or infinite");
        return x;
    }
    double positive(const Json& v, const std::string& where) const {
        const double x = number(v, where);
        if (!(x > 0.0)) fail(where, "must be > 0, got " + v.dump());
        return x;
    }
    const Json& array(const Json& v, const std::string& where) const {
        if (!v.is_array()) fail(where, "must be an array, got " + v.dump());
        return v;
    }
    // An array of `size` numbers >= 0 (size < 0: any length).
    std::vector<double> values(const Json& v, const std::string& where, long long size) const {
        array(v, where);
        if (size >= 0 && static_cast<long long>(v.size()) != size)
            fail(where, "must have " + std::to_string(size) + " numbers, got " + std::to_string(v.size()));
        std::vector<double> out;
        for (size_t i = 0; i < v.size(); ++i) {
            out.push_back(number(v[i], at(where, i)));
            if (out.back() < 0.0) fail(at(where, i), "must be >= 0, got " + v[i].dump());
        }
        return out;
    }
    int class_index(const Json& v, const PcfModel& m, const std::string& where) const {
        if (!v.is_string()) fail(where, "must be a class name, got " + v.dump());
        const auto it = std::find(m.classes.begin(), m.classes.end(), v.get<std::string>());
        if (it == m.classes.end()) fail(where, "unknown class " + v.dump());
        return static_cast<int>(it - m.classes.begin());
    }

    void read_settings(const Json& v, PcfAnalysisSettings& s) const {
        object(v, "settings");
        keys(v, {"sigma", "step", "extent"}, "settings");
        s.sigma = positive(v["sigma"], "settings.sigma");
        s.step = positive(v["step"], "settings.step");
        s.extent = positive(v["extent"], "settings.extent");
        try {
            pcf::check_analysis_settings(s);
        } catch (const Error& e) {
            fail("settings", e.what());
        }
    }

    void read_classes(const Json& v, PcfModel& m) const {
        array(v, "classes");
        if (v.empty()) fail("classes", "must not be empty");
        std::vector<ElementType> types;  // for the dependency graph's checks
        for (size_t c = 0; c < v.size(); ++c) {
            const std::string where = at("classes", c);
            object(v[c], where);
            keys(v[c], {"name", "count", "depends_on", "radii"}, where);
            const Json& name = v[c]["name"];
            if (!name.is_string() || name.get<std::string>().empty())
                fail(at(where, "name"), "must be a non-empty string, got " + name.dump());
            if (std::find(m.classes.begin(), m.classes.end(), name.get<std::string>()) != m.classes.end())
                fail(at(where, "name"), "class " + name.dump() + " is listed twice");
            m.classes.push_back(name.get<std::string>());
            const Json& count = v[c]["count"];
            if (!count.is_number_integer() || count.get<long long>() < 1 || count.get<long long>() > 1'000'000'000)
                fail(at(where, "count"), "must be an integer >= 1, got " + count.dump());
            m.counts.push_back(static_cast<int>(count.get<long long>()));
            m.radii.push_back(values(v[c]["radii"], at(where, "radii"), m.counts.back()));
            if (!std::is_sorted(m.radii.back().begin(), m.radii.back().end(), std::greater<>()))
                fail(at(where, "radii"), "must be sorted largest first");
            m.disks = m.disks || (!m.radii.back().empty() && m.radii.back().front() > 0.0);
            ElementType t;
            t.name = m.classes.back();
            t.depends_on.emplace();
            const Json& deps = array(v[c]["depends_on"], at(where, "depends_on"));
            for (size_t k = 0; k < deps.size(); ++k) {
                if (!deps[k].is_string()) fail(at(at(where, "depends_on"), k), "must be a class name, got " + deps[k].dump());
                t.depends_on->push_back(deps[k].get<std::string>());
            }
            types.push_back(std::move(t));
        }
        try {
            m.parents = pcf::dependency_parents(types);
        } catch (const Error& e) {
            fail("classes", e.what());
        }
    }

    void read_order(const Json& v, PcfModel& m) const {
        array(v, "order");
        if (v.size() != m.classes.size())
            fail("order", "must list each of the " + std::to_string(m.classes.size()) + " classes once");
        std::vector<bool> placed(m.classes.size(), false);
        for (size_t k = 0; k < v.size(); ++k) {
            const int c = class_index(v[k], m, at("order", k));
            if (placed[c]) fail(at("order", k), "class " + v[k].dump() + " is listed twice");
            for (int p : m.parents[c])
                if (!placed[p]) fail(at("order", k), "class " + v[k].dump() + " comes before its parent '" + m.classes[p] + "'");
            placed[c] = true;
            m.order.push_back(c);
        }
    }

    void read_axis(const Json& v, PcfModel& m) const {
        const pcf::Axis axis = pcf::make_axis(m.settings, m.disks);
        m.x = values(v, "x", axis.bins);
        for (int k = 0; k < axis.bins; ++k)
            if (std::abs(m.x[k] - axis.x(k)) > 1e-9 * std::max(1.0, axis.x(k)))
                fail(at("x", static_cast<size_t>(k)), "must be " + std::to_string(k) + " x settings.step");
    }

    void read_pcfs(const Json& v, PcfModel& m) const {
        array(v, "pcfs");
        // Exactly one PCF per class and per dependency edge.
        std::set<std::pair<int, int>> expected, seen;
        for (size_t c = 0; c < m.classes.size(); ++c) {
            expected.insert({static_cast<int>(c), static_cast<int>(c)});
            for (int p : m.parents[c]) expected.insert({p, static_cast<int>(c)});
        }
        const long long bins = static_cast<long long>(m.x.size());
        for (size_t q = 0; q < v.size(); ++q) {
            const std::string where = at("pcfs", q);
            object(v[q], where);
            keys(v[q], {"child", "parent", "mean", "lower", "upper"}, where);
            PcfEnvelope e;
            e.child = class_index(v[q]["child"], m, at(where, "child"));
            e.parent = class_index(v[q]["parent"], m, at(where, "parent"));
            if (!expected.count({e.parent, e.child}))
                fail(where, "'" + m.classes[e.child] + "' does not depend on '" + m.classes[e.parent] + "'");
            if (!seen.insert({e.parent, e.child}).second) fail(where, "the PCF is listed twice");
            e.mean = values(v[q]["mean"], at(where, "mean"), bins);
            e.lower = values(v[q]["lower"], at(where, "lower"), bins);
            e.upper = values(v[q]["upper"], at(where, "upper"), bins);
            for (long long k = 0; k < bins; ++k)
                if (e.lower[k] > e.upper[k])
                    fail(at(at(where, "lower"), static_cast<size_t>(k)), "is above upper");
            m.pcfs.push_back(std::move(e));
        }
        for (const auto& [p, c] : expected)
            if (!seen.count({p, c}))
                fail("pcfs", p == c ? "missing the PCF of class '" + m.classes[c] + "'"
                                    : "missing the PCF of '" + m.classes[c] + "' on '" + m.classes[p] + "'");
    }

    // Per class (name -> value) for every class but `own`; values >= 0.
    std::vector<double> per_class(const Json& v, const PcfModel& m, int own, const std::string& where) const {
        object(v, where);
        std::vector<double> out(m.classes.size(), 0.0);
        for (auto it = v.begin(); it != v.end(); ++it) {
            const int o = class_index(Json(it.key()), m, at(where, it.key()));
            if (o == own) fail(at(where, it.key()), "is the class itself");
            out[o] = number(it.value(), at(where, it.key()));
            if (out[o] < 0.0) fail(at(where, it.key()), "must be >= 0, got " + it.value().dump());
        }
        return out;
    }

    // One per class with fewer than kPcfSparseCount elements, in class order.
    void read_sparse(const Json& v, PcfModel& m) const {
        array(v, "sparse");
        for (size_t q = 0; q < v.size(); ++q) {
            const std::string where = at("sparse", q);
            object(v[q], where);
            keys(v[q], {"class", "spacing", "closest", "tether"}, where);
            PcfSparseClass s;
            s.cls = class_index(v[q]["class"], m, at(where, "class"));
            if (m.counts[s.cls] >= kPcfSparseCount)
                fail(at(where, "class"), "'" + m.classes[s.cls] + "' has " + std::to_string(m.counts[s.cls]) +
                                             " elements, enough for its PCFs");
            if (!m.sparse.empty() && m.sparse.back().cls >= s.cls) fail(where, "must be in class order, once each");
            s.spacing = number(v[q]["spacing"], at(where, "spacing"));
            if (s.spacing < 0.0) fail(at(where, "spacing"), "must be >= 0, got " + v[q]["spacing"].dump());
            s.closest = per_class(v[q]["closest"], m, s.cls, at(where, "closest"));
            s.tether = per_class(v[q]["tether"], m, s.cls, at(where, "tether"));
            m.sparse.push_back(std::move(s));
        }
    }

    // Exactly one per pair of classes without a dependency between them, a before b.
    void read_separations(const Json& v, PcfModel& m) const {
        array(v, "separations");
        const int classes = static_cast<int>(m.classes.size());
        const auto depends = [&](int child, int parent) {
            return std::find(m.parents[child].begin(), m.parents[child].end(), parent) != m.parents[child].end();
        };
        std::set<std::pair<int, int>> seen;
        for (size_t q = 0; q < v.size(); ++q) {
            const std::string where = at("separations", q);
            object(v[q], where);
            keys(v[q], {"a", "b", "x"}, where);
            PcfSeparation sep;
            sep.a = class_index(v[q]["a"], m, at(where, "a"));
            sep.b = class_index(v[q]["b"], m, at(where, "b"));
            if (sep.a >= sep.b) fail(where, "a must be a class listed before b");
            if (depends(sep.a, sep.b) || depends(sep.b, sep.a))
                fail(where, "'" + m.classes[sep.a] + "' and '" + m.classes[sep.b] + "' have a PCF between them");
            if (!seen.insert({sep.a, sep.b}).second) fail(where, "the pair is listed twice");
            sep.x = number(v[q]["x"], at(where, "x"));
            if (sep.x < 0.0) fail(at(where, "x"), "must be >= 0, got " + v[q]["x"].dump());
            m.separations.push_back(sep);
        }
        for (int a = 0; a < classes; ++a)
            for (int b = a + 1; b < classes; ++b)
                if (!depends(a, b) && !depends(b, a) && !seen.count({a, b}))
                    fail("separations", "missing the pair '" + m.classes[a] + "', '" + m.classes[b] + "'");
    }
};

}  // namespace

std::string pcf_model_to_json(const PcfModel& m) {
    const auto name = [&](int c) { return m.classes.at(static_cast<size_t>(c)); };
    std::string out = "{\n";
    out += std::string("  \"format\": \"") + model_format + "\",\n";
    out += "  \"version\": " + std::to_string(model_version) + ",\n";
    const OrderedJson settings{{"sigma", m.settings.sigma}, {"step", m.settings.step}, {"extent", m.settings.extent}};
    out += "  \"settings\": " + settings.dump() + ",\n";
    out += "  \"r_max\": " + OrderedJson(m.r_max).dump() + ",\n";
    out += "  \"area\": " + OrderedJson(m.area).dump() + ",\n";
    out += "  \"classes\": [\n";
    for (size_t c = 0; c < m.classes.size(); ++c) {
        OrderedJson cls{{"name", m.classes[c]}, {"count", m.counts.at(c)}};
        OrderedJson deps = OrderedJson::array();
        for (int p : m.parents.at(c)) deps.push_back(name(p));
        cls["depends_on"] = deps;
        cls["radii"] = m.radii.at(c);
        out += "    " + cls.dump() + (c + 1 < m.classes.size() ? ",\n" : "\n");
    }
    out += "  ],\n";
    OrderedJson order = OrderedJson::array();
    for (int c : m.order) order.push_back(name(c));
    out += "  \"order\": " + order.dump() + ",\n";
    out += "  \"x\": " + OrderedJson(m.x).dump() + ",\n";
    out += "  \"pcfs\": [\n";
    for (size_t q = 0; q < m.pcfs.size(); ++q) {
        const PcfEnvelope& e = m.pcfs[q];
        out += "    {\"child\": " + OrderedJson(name(e.child)).dump() + ", \"parent\": " +
               OrderedJson(name(e.parent)).dump() + ",\n";
        out += "     \"mean\": " + OrderedJson(e.mean).dump() + ",\n";
        out += "     \"lower\": " + OrderedJson(e.lower).dump() + ",\n";
        out += "     \"upper\": " + OrderedJson(e.upper).dump() + "}";
        out += q + 1 < m.pcfs.size() ? ",\n" : "\n";
    }
    out += "  ],\n";
    out += "  \"separations\": [";
    for (size_t q = 0; q < m.separations.size(); ++q) {
        const PcfSeparation& sep = m.separations[q];
        const OrderedJson item{{"a", name(sep.a)}, {"b", name(sep.b)}, {"x", sep.x}};
        out += (q == 0 ? "\n    " : ",\n    ") + item.dump();
    }
    out += m.separations.empty() ? "]" : "\n  ]";
    out += ",\n  \"sparse\": [";
    for (size_t q = 0; q < m.sparse.size(); ++q) {
        const PcfSparseClass& s = m.sparse[q];
        OrderedJson closest = OrderedJson::object(), tether = OrderedJson::object();
        for (size_t o = 0; o < m.classes.size(); ++o) {
            if (static_cast<int>(o) == s.cls) continue;
            closest[m.classes[o]] = s.closest.at(o);
            if (s.tether.at(o) > 0.0) tether[m.classes[o]] = s.tether[o];
        }
        const OrderedJson item{{"class", name(s.cls)}, {"spacing", s.spacing}, {"closest", closest}, {"tether", tether}};
        out += (q == 0 ? "\n    " : ",\n    ") + item.dump();
    }
    out += m.sparse.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

PcfModel pcf_model_from_json(const std::string& text, const std::string& source) {
    return ModelReader(source).read(text);
}

}  // namespace tessera
