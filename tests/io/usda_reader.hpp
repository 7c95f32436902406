// A strict reader of the USD text layers tessera writes (src/geometry/write_usda.cpp),
// for the tests: it accepts the subset of .usda the writer uses — layer metadata, prims
// (def / over, typed or not, with metadata), attributes (custom, uniform, array types,
// metadata, time samples) and relationships — and throws std::runtime_error on anything else: an
// unknown token, an unknown value type, a value that does not match its declared type
// (point3f must be 3 numbers, quath 4, int an integer), a repeated prim or property.
// It is not a USD parser; it checks that the writer's output is what it means to be.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace usda_test {

struct Value {
    enum Kind { number, string, path, tuple, list } kind = number;
    double x = 0.0;
    std::string text;          // string contents (unescaped) or path
    std::vector<Value> items;  // tuple or list
};

struct Property {
    std::string type;  // "point3f", "rel" for relationships
    bool array = false, custom = false, uniform = false;
    Value value;  // the value; for time samples, the first sample's
    std::map<std::string, Value> metadata;
    // `name.timeSamples = {code: value, ...}`: the values by time code, in order.
    std::vector<std::pair<double, Value>> samples;
};

struct Prim {
    std::string specifier, type, name, path;
    std::map<std::string, Value> metadata;
    std::map<std::string, Property> properties;
    std::vector<Prim> children;

    const Property& property(const std::string& name) const {
        const auto it = properties.find(name);
        if (it == properties.end()) throw std::runtime_error(path + " has no property " + name);
        return it->second;
    }
    bool has(const std::string& name) const { return properties.count(name) > 0; }
};

struct Layer {
    std::map<std::string, Value> metadata;
    std::vector<Prim> prims;

    // The prim at an absolute path such as "/World/Elements", or nullptr.
    const Prim* find(const std::string& path) const {
        const std::vector<Prim>* level = &prims;
        const Prim* found = nullptr;
        size_t start = 1;
        while (start <= path.size()) {
            const size_t slash = path.find('/', start);
            const std::string name =
                path.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
            found = nullptr;
            for (const Prim& p : *level)
                if (p.name == name) found = &p;
            if (!found) return nullptr;
            level = &found->children;
            if (slash == std::string::npos) break;
            start = slash + 1;
        }
        return found;
    }
};

class Reader {
public:
    explicit Reader(std::string text) : s_(std::move(text)) {}

    Layer read() {
        const std::string header = "#usda 1.0\n";
        if (s_.compare(0, header.size(), header) != 0) fail("the layer must start with '#usda 1.0'");
        i_ = header.size();
        Layer layer;
        if (peek() == "(") layer.metadata = metadata();
        while (!at_end()) {
            layer.prims.push_back(prim(""));
            for (size_t k = 0; k + 1 < layer.prims.size(); ++k)
                if (layer.prims[k].name == layer.prims.back().name)
                    fail("repeated prim " + layer.prims.back().name);
        }
        return layer;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        size_t line = 1;
        for (size_t k = 0; k < i_ && k < s_.size(); ++k) line += s_[k] == '\n';
        throw std::runtime_error("usda line " + std::to_string(line) + ": " + what);
    }

    void skip_space() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    bool at_end() {
        skip_space();
        return i_ >= s_.size();
    }
    static bool word_char(char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':';
    }

    // The next token without consuming it: punctuation, a word, a number, "..." or <...>.
    std::string peek() {
        const size_t at = (skip_space(), i_);
        std::string token = next();
        i_ = at;
        return token;
    }
    std::string next() {
        skip_space();
        if (i_ >= s_.size()) fail("unexpected end of the layer");
        const char c = s_[i_];
        if (std::string("()[]{},=:").find(c) != std::string::npos) return std::string(1, s_[i_++]);
        const size_t start = i_;
        if (c == '"') {
            for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_) {
                if (s_[i_] == '\n') fail("a line break inside a string");
                if (s_[i_] == '\\') ++i_;  // the escaped character
            }
            if (i_ >= s_.size()) fail("an unterminated string");
            return s_.substr(start, ++i_ - start);
        }
        if (c == '<') {
            const size_t end = s_.find('>', i_);
            if (end == std::string::npos) fail("an unterminated path");
            i_ = end + 1;
            return s_.substr(start, i_ - start);
        }
        if (c == '-' || c == '+' || c == '.' || std::isdigit(static_cast<unsigned char>(c))) {
            while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) ||
                                      std::string("+-.").find(s_[i_]) != std::string::npos))
                ++i_;
            return s_.substr(start, i_ - start);
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (i_ < s_.size() && word_char(s_[i_])) ++i_;
            return s_.substr(start, i_ - start);
        }
        fail(std::string("unexpected character '") + c + "'");
    }
    void expect(const std::string& token) {
        const std::string t = next();
        if (t != token) fail("expected '" + token + "', got '" + t + "'");
    }

    static std::string unescape(const std::string& quoted) {
        std::string out;
        for (size_t k = 1; k + 1 < quoted.size(); ++k) {
            if (quoted[k] != '\\') {
                out += quoted[k];
                continue;
            }
            const char e = quoted[++k];
            if (e == 'n') {
                out += '\n';
            } else if (e == 'x') {
                out += static_cast<char>(std::strtol(quoted.substr(k + 1, 2).c_str(), nullptr, 16));
                k += 2;
            } else {
                out += e;
            }
        }
        return out;
    }

    Value value() {
        const std::string t = next();
        Value v;
        if (t == "(" || t == "[") {
            v.kind = t == "(" ? Value::tuple : Value::list;
            const std::string close = t == "(" ? ")" : "]";
            if (peek() == close) {
                next();
                return v;
            }
            while (true) {
                v.items.push_back(value());
                const std::string sep = next();
                if (sep == close) return v;
                if (sep != ",") fail("expected ',' or '" + close + "', got '" + sep + "'");
            }
        }
        if (t[0] == '"' || t[0] == '<') {
            v.kind = t[0] == '"' ? Value::string : Value::path;
            v.text = t[0] == '"' ? unescape(t) : t.substr(1, t.size() - 2);
            return v;
        }
        char* end = nullptr;
        v.x = std::strtod(t.c_str(), &end);
        if (end != t.c_str() + t.size() || !std::isfinite(v.x)) fail("'" + t + "' is not a value");
        return v;
    }

    std::map<std::string, Value> metadata() {
        expect("(");
        std::map<std::string, Value> out;
        while (peek() != ")") {
            const std::string key = next();
            if (!word_char(key[0]) || std::isdigit(static_cast<unsigned char>(key[0])))
                fail("bad metadata key '" + key + "'");
            expect("=");
            if (!out.emplace(key, value()).second) fail("repeated metadata " + key);
        }
        expect(")");
        return out;
    }

    // Components of each value type, 0 for text, -1 for an integer scalar.
    int components(const std::string& type) {
        static const std::map<std::string, int> table = {
            {"point3f", 3}, {"normal3f", 3}, {"float3", 3}, {"color3f", 3}, {"quath", 4},
            {"quatf", 4},   {"double", 1},   {"float", 1},  {"bool", -1},   {"int", -1},
            {"int64", -1},  {"string", 0},   {"token", 0}};
        const auto it = table.find(type);
        if (it == table.end()) fail("unknown value type '" + type + "'");
        return it->second;
    }
    void check_scalar(const Value& v, int n) {
        if (n == 0 && v.kind != Value::string) fail("expected a string");
        if (n == 1 && v.kind != Value::number) fail("expected a number");
        if (n == -1 && (v.kind != Value::number || v.x != std::floor(v.x))) fail("expected an integer");
        if (n > 1) {
            if (v.kind != Value::tuple || static_cast<int>(v.items.size()) != n)
                fail("expected a tuple of " + std::to_string(n));
            for (const Value& c : v.items) check_scalar(c, 1);
        }
    }

    Prim prim(const std::string& parent) {
        Prim p;
        p.specifier = next();
        if (p.specifier != "def" && p.specifier != "over")
            fail("expected def or over, got '" + p.specifier + "'");
        std::string t = next();
        if (t[0] != '"') {
            p.type = t;
            t = next();
        }
        if (t[0] != '"') fail("expected a prim name");
        p.name = unescape(t);
        p.path = parent + "/" + p.name;
        if (peek() == "(") p.metadata = metadata();
        expect("{");
        while (peek() != "}") {
            const std::string word = peek();
            if (word == "def" || word == "over") {
                p.children.push_back(prim(p.path));
                for (size_t k = 0; k + 1 < p.children.size(); ++k)
                    if (p.children[k].name == p.children.back().name)
                        fail("repeated prim " + p.children.back().path);
                continue;
            }
            property(p);
        }
        expect("}");
        return p;
    }

    void property(Prim& p) {
        Property prop;
        std::string word = next();
        if (word == "rel") {
            prop.type = "rel";
            const std::string name = next();
            expect("=");
            prop.value = value();
            if (prop.value.kind != Value::list) fail("a relationship's targets must be a list");
            for (const Value& target : prop.value.items)
                if (target.kind != Value::path) fail("a relationship target must be a path");
            if (!p.properties.emplace(name, prop).second) fail("repeated property " + name);
            return;
        }
        if (word == "custom") {
            prop.custom = true;
            word = next();
        }
        if (word == "uniform") {
            prop.uniform = true;
            word = next();
        }
        prop.type = word;
        const int n = components(word);
        if (peek() == "[") {
            next();
            expect("]");
            prop.array = true;
        }
        const std::string name = next();
        if (!word_char(name[0])) fail("expected a property name, got '" + name + "'");
        const bool sampled = i_ < s_.size() && s_[i_] == '.';
        if (sampled) {
            ++i_;
            if (next() != "timeSamples") fail("expected timeSamples after '" + name + ".'");
        }
        expect("=");
        if (sampled) {
            prop.samples = time_samples(prop, n, name);
            if (prop.samples.empty()) fail(name + " has no time sample");
            prop.value = prop.samples.front().second;
        } else {
            prop.value = value();
            check_value(prop, n, name, prop.value);
        }
        if (peek() == "(") prop.metadata = metadata();
        if (!p.properties.emplace(name, prop).second) fail("repeated property " + name);
    }

    void check_value(const Property& prop, int n, const std::string& name, const Value& v) {
        if (prop.array) {
            if (v.kind != Value::list) fail(name + " must be an array");
            for (const Value& item : v.items) check_scalar(item, n);
        } else {
            check_scalar(v, n);
        }
    }

    // {code: value, ...} with increasing codes and an optional trailing comma.
    std::vector<std::pair<double, Value>> time_samples(const Property& prop, int n, const std::string& name) {
        std::vector<std::pair<double, Value>> out;
        expect("{");
        while (peek() != "}") {
            const Value code = value();
            if (code.kind != Value::number) fail(name + ": a time code must be a number");
            if (!out.empty() && !(code.x > out.back().first)) fail(name + ": time codes must increase");
            expect(":");
            out.emplace_back(code.x, value());
            check_value(prop, n, name, out.back().second);
            if (peek() == ",") next();
        }
        expect("}");
        return out;
    }

    std::string s_;
    size_t i_ = 0;
};

inline Layer read_usda(const std::string& text) {
    return Reader(text).read();
}

}  // namespace usda_test
