// The checked reading of a JSON document's fields (core/io/patchwork_format.cpp): each accessor checks
// the value's type and range and, on failure, throws InputError naming the file and the field's
// JSON path ("patches[3].idx[7]"). Header-only; used by the .patchwork reader.
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/json_guard.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace base {
namespace json_reader {

using nlohmann::json;

inline std::string at(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }
inline std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

class Reader {
public:
    // `prefix`: where the document sits in the file ("asset.extras.patchwork" in a glTF).
    explicit Reader(const std::string& source, std::string prefix = {}) : source_(source), prefix_(std::move(prefix)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& why) const {
        const std::string field = prefix_.empty() ? path : path.empty() ? prefix_ : prefix_ + (path[0] == '[' ? "" : ".") + path;
        throw InputError(source_, why, 0, field);
    }

    [[noreturn]] void wrongType(const json& v, const std::string& path, const char* expected) const {
        fail(path, std::string("expected ") + expected + ", found " + describe(v));
    }

    static std::string describe(const json& v) {
        if (v.is_number_float()) return "a fractional number";
        if (v.is_number_integer()) return "an integer";
        if (v.is_null()) return "null";
        if (v.is_array()) return "an array";
        if (v.is_object()) return "an object";
        if (v.is_boolean()) return "a boolean";
        if (v.is_string()) return "a string";
        return v.type_name();
    }

    const json& object(const json& v, const std::string& path) const {
        if (!v.is_object()) wrongType(v, path, "an object");
        return v;
    }

    // Member `key` of object `obj` (at `path`), or nullptr when absent and optional.
    const json* member(const json& obj, const std::string& path, const char* key, bool required) const {
        auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) fail(at(path, key), "required field is missing");
            return nullptr;
        }
        return &*it;
    }

    const json& array(const json& v, const std::string& path, size_t maxSize, const char* what) const {
        if (!v.is_array()) wrongType(v, path, "an array");
        if (v.size() > maxSize) fail(path, std::to_string(v.size()) + " " + what + "; the limit is " + std::to_string(maxSize));
        return v;
    }

    const json& fixedArray(const json& v, const std::string& path, size_t n) const {
        if (!v.is_array()) wrongType(v, path, ("an array of " + std::to_string(n)).c_str());
        if (v.size() != n) fail(path, "expected an array of " + std::to_string(n) + " elements, found " + std::to_string(v.size()));
        return v;
    }

    double number(const json& v, const std::string& path) const {
        if (!v.is_number()) wrongType(v, path, "a number");
        const double d = v.get<double>();
        if (!std::isfinite(d)) fail(path, "number is not finite");
        return d;
    }

    double numberInRange(const json& v, const std::string& path, double lo, double hi, bool openLo = false) const {
        const double d = number(v, path);
        if (d < lo || d > hi || (openLo && d == lo))
            fail(path, "value " + shortNumber(d) + " is outside " + (openLo ? "(" : "[") + shortNumber(lo) + ", " + shortNumber(hi) + "]");
        return d;
    }

    double coordinate(const json& v, const std::string& path) const {
        const double d = number(v, path);
        if (std::abs(d) > limits::kMaxCoordinate) fail(path, "coordinate " + shortNumber(d) + " is too large (the limit is ±1e9)");
        return d;
    }

    float floatValue(const json& v, const std::string& path, double lo = -std::numeric_limits<float>::max(),
                     double hi = std::numeric_limits<float>::max()) const {
        return static_cast<float>(numberInRange(v, path, lo, hi));
    }

    bool boolean(const json& v, const std::string& path) const {
        if (!v.is_boolean()) wrongType(v, path, "true or false");
        return v.get<bool>();
    }

    std::string string(const json& v, const std::string& path) const {
        if (!v.is_string()) wrongType(v, path, "a string");
        return v.get<std::string>();
    }

    // A non-negative integer below `limit`.
    uint64_t index(const json& v, const std::string& path, uint64_t limit, const char* what) const {
        if (!v.is_number_integer()) wrongType(v, path, "a non-negative integer");
        if (!v.is_number_unsigned() && v.get<int64_t>() < 0)
            fail(path, "negative " + std::string(what) + " " + std::to_string(v.get<int64_t>()));
        const uint64_t i = v.is_number_unsigned() ? v.get<uint64_t>() : static_cast<uint64_t>(v.get<int64_t>());
        if (i >= limit)
            fail(path, std::string(what) + " " + std::to_string(i) + " is out of range (" +
                           (limit == 0 ? std::string("there are none") : "0.." + std::to_string(limit - 1)) + ")");
        return i;
    }

    template <typename E>
    E named(const json& v, const std::string& path, std::optional<E> (*parse)(std::string_view), const char* choices) const {
        const std::string s = string(v, path);
        if (auto e = parse(s)) return *e;
        fail(path, "unknown value '" + s + "'; expected one of " + choices);
    }

    // Optional field helpers: assign when present.
    template <typename F>
    void optional(const json& obj, const std::string& path, const char* key, F&& read) const {
        if (const json* v = member(obj, path, key, false)) read(*v, at(path, key));
    }

    static std::string shortNumber(double d) {
        char buf[32];
        auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, d);
        return ec == std::errc() ? std::string(buf, ptr) : std::string("?");
    }

private:
    const std::string& source_;
    std::string prefix_;
};

}  // namespace json_reader
}  // namespace base
}  // namespace pw
