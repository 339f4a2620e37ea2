// Values between Python and the library (the compiled module's part; bindings.cpp): numbers,
// vectors and arrays read as the CLI reads them, JSON both ways, warnings.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdlib>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "momentlab/momentlab.hpp"

namespace momentlab::python {

namespace py = pybind11;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Rows of k doubles as a numpy array of shape (rows, k), copied.
template <int K, class V>
Array rows(const std::vector<V>& vs) {
    Array out({static_cast<py::ssize_t>(vs.size()), static_cast<py::ssize_t>(K)});
    auto a = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < vs.size(); ++i) {
        for (int k = 0; k < K; ++k) {
            // A value beyond a double is refused as the CLI refuses to print it (never inf).
            if constexpr (std::is_same_v<V, ExactVector>) {
                a(static_cast<py::ssize_t>(i), k) = output_value(vs[i].value()(k));
            } else {
                a(static_cast<py::ssize_t>(i), k) = output_value(vs[i](k));
            }
        }
    }
    return out;
}

// Real numbers as float64, as the CLI reads them: other dtypes (strings, complex, objects) and
// masked arrays are refused, and a long double that would underflow to 0 is refused as in files.
Array real_array(const py::handle& value, const std::string& what);

// A vector by the one rule of every front end (app/checks.hpp): finite, its largest coordinate 0
// or of magnitude 1e-60 .. 1e60.
template <class V>
void check_magnitude(const V& v, const std::string& what) {
    if constexpr (V::RowsAtCompileTime == 2 || V::RowsAtCompileTime == 3) {
        (void)checked_vector(v, what);
    } else {
        for (Eigen::Index k = 0; k < v.size(); ++k) (void)checked_number(v(k), what);
    }
}

// A number in the CLI's range; `what` names it in errors.
double number_of(double x, const std::string& what);

// A finite vector of K coordinates from anything numpy reads as one; `what` names it in errors.
template <int K>
Eigen::Matrix<double, K, 1> vector_of(const py::handle& value, const char* what) {
    const Array a = real_array(value, what);
    if (a.ndim() != 1 || a.shape(0) != K) throw InputError(what, "expected " + std::to_string(K) + " numbers");
    Eigen::Matrix<double, K, 1> v;
    for (int k = 0; k < K; ++k) v(k) = a.at(k);
    check_magnitude(v, what);
    return v;
}

// The text without the blanks every front end strips around a number (space, tab, CR, LF).
std::string stripped(std::string text);

// A Python or numpy bool (not a number here, though numpy reads True as 1).
bool is_bool(const py::handle& x);

// A number with its exact meaning (docs/design.md, "Numbers as typed"): a float (or numpy
// scalar) is its binary value, an int its integer, a fractions.Fraction its ratio, a
// decimal.Decimal or a numeric string the decimal it spells; nullopt for anything else.
std::optional<Rational> exact_number(const py::handle& x);

// True for a list or tuple holding a Fraction, a Decimal, a string or an int beyond 2^53 (read
// exactly, element by element); numpy arrays, floats and small ints take vector_of's path.
bool needs_exact(const py::handle& value);

// A vector of K exact numbers (exact_number; floats and numpy arrays as vector_of reads them),
// checked as vector_of checks its rounding.
template <int K>
std::array<Rational, K> exact_vector_of(const py::handle& value, const char* what) {
    std::array<Rational, K> out;
    if (!needs_exact(value)) {
        const Eigen::Matrix<double, K, 1> v = vector_of<K>(value, what);
        for (int k = 0; k < K; ++k) out[static_cast<std::size_t>(k)] = Rational(v(k));
        return out;
    }
    if (py::len(value) != K) throw InputError(what, "expected " + std::to_string(K) + " numbers");
    Eigen::Matrix<double, K, 1> rounded;
    int k = 0;
    for (const py::handle& x : value) {
        if (is_bool(x)) throw InputError(what, "expected numbers, got a bool");
        std::optional<Rational> r = exact_number(x);
        // As in files and options: a non-zero number never reads as 0 (docs/reliability.md).
        if (r && !r->is_zero() && r->to_double() == 0.0) {
            throw InputError(what, "a number is " + std::string(kTooSmallForADouble));
        }
        if (!r && py::isinstance<py::str>(x)) {
            // A decimal whose exponent takes it beyond the doubles (1e-999999999): as files say it.
            const std::string t = stripped(x.cast<std::string>());
            if (!Rational::is_decimal(t)) throw InputError(what, "expected numbers");
            if (std::strtod(t.c_str(), nullptr) == 0.0) throw InputError(what, "a number is " + std::string(kTooSmallForADouble));
            throw InputError(what, "expected finite numbers");
        }
        if (!r) {
            if (!py::hasattr(x, "__float__")) throw InputError(what, "expected numbers");
            double d = 0.0;
            try {
                d = x.attr("__float__")().cast<double>();
            } catch (const py::error_already_set&) {  // Decimal('sNaN')
                throw InputError(what, "expected finite numbers");
            }
            if (!std::isfinite(d)) throw InputError(what, "expected finite numbers");
            // A non-zero value that rounds to 0 (a long double or a Decimal below the doubles'
            // range) is refused, as in files: never read as 0.
            if (d == 0.0 && py::bool_(py::reinterpret_borrow<py::object>(x)).cast<bool>()) {
                throw InputError(what, "a number is " + std::string(kTooSmallForADouble));
            }
            r = Rational(d);
        }
        rounded(k) = r->to_double();
        out[static_cast<std::size_t>(k++)] = *r;
    }
    check_magnitude(rounded, what);
    return out;
}

// An (n, 3) array of finite wrenches or normals; `what` names it in errors.
std::vector<Vec3> vectors3_of(const py::handle& value, const char* what);

// A polygon: an (n, 2) array of finite vertices (find_contacts checks that it is simple).
Polygon polygon_of(const py::handle& value, const std::string& what);

// A Python value (dict, list, tuple, numpy array, number, string, bool, None) as JSON, so that
// the library's readers check it and name the path of a bad field.
nlohmann::json json_of(const py::handle& value, const std::string& path, int depth = 0);

// JSON answers (plans) as plain Python values.
py::object python_of(const nlohmann::json& j);

// Warnings as Python's UserWarning, pointing at the caller's line; under `-W error` the first
// one is raised.
void warn_all(const InputWarnings& warnings);

}  // namespace momentlab::python
