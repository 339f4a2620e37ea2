#include "values.hpp"

#include <cmath>
#include <string>

namespace momentlab::python {

// Real numbers as float64, as the CLI reads them: other dtypes (strings, complex, objects) and
// masked arrays are refused, and a long double that would underflow to 0 is refused as in files.
namespace {

// True when a list (or tuple), or one in it, holds a bool: numpy would read it as 0 or 1.
bool holds_bool(const py::handle& value, int depth = 0) {
    if (depth > 2 || (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value))) return false;
    for (const py::handle& x : value) {
        if (is_bool(x) || holds_bool(x, depth + 1)) return true;
    }
    return false;
}

}  // namespace

std::string stripped(std::string t) {
    t.erase(t.find_last_not_of(" \t\r\n") + 1);
    t.erase(0, std::min(t.size(), t.find_first_not_of(" \t\r\n")));
    return t;
}

bool is_bool(const py::handle& x) {
    static const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
    return py::isinstance<py::bool_>(x) || py::isinstance(x, numpy_bool);
}

Array real_array(const py::handle& value, const std::string& what) {
    const py::module_ np = py::module_::import("numpy");
    if (holds_bool(value)) throw InputError(what, "expected numbers, got a bool");
    if (np.attr("ma").attr("isMaskedArray")(value).cast<bool>()) {
        throw InputError(what, "a masked array is not read (fill it first)");
    }
    py::array raw;
    try {
        raw = np.attr("asarray")(value);
    } catch (const py::error_already_set&) {
        throw InputError(what, "expected numbers");
    }
    const char kind = raw.dtype().kind();
    if (kind != 'i' && kind != 'u' && kind != 'f') {
        throw InputError(what, "expected real numbers, not an array of dtype " + py::str(raw.dtype()).cast<std::string>());
    }
    Array a = Array::ensure(raw);
    if (kind == 'f' && raw.dtype().itemsize() > 8) {
        const py::object tiny = np.attr("logical_and")(np.attr("equal")(a, 0.0), np.attr("not_equal")(raw, 0));
        if (np.attr("any")(tiny).cast<bool>()) throw InputError(what, "a number is " + std::string(kTooSmallForADouble));
    }
    return a;
}

// A number in the CLI's range; `what` names it in errors.
double number_of(double x, const std::string& what) { return checked_number(x, what); }

// A number with its exact meaning (docs/design.md, "Numbers as typed"): a float (or numpy
// scalar) is its binary value, an int its integer, a fractions.Fraction its ratio, a
// decimal.Decimal or a numeric string the decimal it spells; nullopt for anything else.
std::optional<Rational> exact_number(const py::handle& x) {
    static const py::object fraction = py::module_::import("fractions").attr("Fraction");
    static const py::object decimal = py::module_::import("decimal").attr("Decimal");
    const auto integer = [](const py::handle& i) { return Rational::parse(py::str(i).cast<std::string>()); };
    if (py::isinstance<py::bool_>(x)) return Rational(x.cast<bool>() ? 1.0 : 0.0);
    if (py::isinstance<py::int_>(x)) return integer(x);
    if (py::isinstance(x, fraction)) {
        const std::optional<Rational> num = integer(x.attr("numerator")), den = integer(x.attr("denominator"));
        if (!num || !den) return std::nullopt;
        return Rational(num->num(), den->num());
    }
    if (py::isinstance(x, decimal)) return Rational::parse(py::str(x).cast<std::string>());
    if (py::isinstance<py::str>(x)) return Rational::parse(stripped(x.cast<std::string>()));
    return std::nullopt;
}

// True for a list or tuple holding a Fraction, a Decimal, a string or an int beyond 2^53 (read
// exactly, element by element); numpy arrays, floats and small ints take vector_of's path.
bool needs_exact(const py::handle& value) {
    if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value)) return false;
    static const py::object fraction = py::module_::import("fractions").attr("Fraction");
    static const py::object decimal = py::module_::import("decimal").attr("Decimal");
    for (const py::handle& x : value) {
        if (py::isinstance<py::str>(x) || py::isinstance(x, fraction) || py::isinstance(x, decimal)) return true;
        if (py::isinstance<py::int_>(x) && !py::isinstance<py::bool_>(x) && x.attr("bit_length")().cast<int>() > 53) return true;
    }
    return false;
}

// An (n, 3) array of finite wrenches or normals; `what` names it in errors.
std::vector<Vec3> vectors3_of(const py::handle& value, const char* what) {
    const Array a = real_array(value, what);
    if (a.ndim() != 2 || a.shape(1) != 3) throw InputError(what, "expected an array of shape (n, 3)");
    std::vector<Vec3> out(static_cast<std::size_t>(a.shape(0)));
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
        out[static_cast<std::size_t>(i)] = Vec3(r(i, 0), r(i, 1), r(i, 2));
        check_magnitude(out[static_cast<std::size_t>(i)], std::string(what) + "[" + std::to_string(i) + "]");
    }
    return out;
}

// A polygon: an (n, 2) array of finite vertices (find_contacts checks that it is simple).
Polygon polygon_of(const py::handle& value, const std::string& what) {
    const Array a = real_array(value, what);
    if (a.ndim() != 2 || a.shape(1) != 2) throw InputError(what, "expected an array of shape (n, 2)");
    Polygon out;
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
        out.emplace_back(r(i, 0), r(i, 1));
        check_magnitude(out.back(), what + "[" + std::to_string(i) + "]");
    }
    return out;
}

// A Python value (dict, list, tuple, numpy array, number, string, bool, None) as JSON, so that
// the library's readers check it and name the path of a bad field.
nlohmann::json json_of(const py::handle& value, const std::string& path, int depth) {
    if (depth > 100) throw InputError(path, "nested more than 100 levels deep (a value that contains itself?)");
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) {
        try {
            return value.cast<long long>();
        } catch (const py::cast_error&) {
            try {  // a big integer: the reader checks its magnitude
                return value.cast<double>();
            } catch (const py::cast_error&) {
                throw InputError(path, "expected a number, " + std::string(kMagnitudeRange));
            } catch (const py::error_already_set&) {
                throw InputError(path, "expected a number, " + std::string(kMagnitudeRange));
            }
        }
    }
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
        nlohmann::json out = nlohmann::json::object();
        for (const auto& [key, item] : value.cast<py::dict>()) {
            if (!py::isinstance<py::str>(key)) throw InputError(path, "keys must be strings");
            const auto name = key.cast<std::string>();
            out[name] = json_of(item, path + "." + name, depth + 1);
        }
        return out;
    }
    const py::module_ np = py::module_::import("numpy");
    if (py::isinstance(value, np.attr("generic"))) {  // a numpy scalar, by its kind
        const char kind = py::str(value.attr("dtype").attr("kind")).cast<std::string>()[0];
        if (kind == 'b') return py::bool_(py::reinterpret_borrow<py::object>(value)).cast<bool>();
        if (kind == 'i' || kind == 'u') return json_of(py::int_(py::reinterpret_borrow<py::object>(value)), path, depth + 1);
        if (kind != 'f') throw InputError(path, "expected a real number");
        const double x = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
        if (x == 0.0 && py::bool_(py::reinterpret_borrow<py::object>(value))) {  // a long double below a double's range
            throw InputError(path, std::string(kTooSmallForADouble));
        }
        return x;
    }
    if (py::isinstance(value, np.attr("ndarray"))) return json_of(value.attr("tolist")(), path, depth + 1);
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        nlohmann::json out = nlohmann::json::array();
        std::size_t i = 0;
        for (const auto& item : value) out.push_back(json_of(item, path + "[" + std::to_string(i++) + "]", depth + 1));
        return out;
    }
    throw InputError(path, std::string("expected a number, list or object, not ") +
                               py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

// JSON answers (plans) as plain Python values.
py::object python_of(const nlohmann::json& j) {
    switch (j.type()) {
        case nlohmann::json::value_t::null: return py::none();
        case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
        case nlohmann::json::value_t::number_integer: return py::int_(j.get<long long>());
        case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
        case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
        case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
        case nlohmann::json::value_t::array: {
            py::list out;
            for (const auto& item : j) out.append(python_of(item));
            return out;
        }
        case nlohmann::json::value_t::object: {
            py::dict out;
            for (const auto& [key, item] : j.items()) out[py::str(key)] = python_of(item);
            return out;
        }
        default: return py::none();
    }
}

// Warnings as Python's UserWarning, pointing at the caller's line; under `-W error` the first
// one is raised.
void warn_all(const InputWarnings& warnings) {
    for (const std::string& w : warnings) {
        if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 3) != 0) throw py::error_already_set();
    }
}

}  // namespace momentlab::python
