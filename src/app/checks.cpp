// The front ends' checks of numbers (app/checks.hpp), each message once.
#include "momentlab/app/checks.hpp"

#include <algorithm>
#include <cmath>

namespace momentlab {

double checked_number(double x, const std::string& where) {
    if (!std::isfinite(x) || !magnitude_in_range(std::fabs(x))) {
        throw InputError(where, "expected a finite number, " + std::string(kMagnitudeRange));
    }
    return x;
}

namespace {

template <class V>
V checked(const V& v, const std::string& where) {
    if (!v.allFinite()) throw InputError(where, "expected finite numbers");
    if (!magnitude_in_range(v.cwiseAbs().maxCoeff())) {
        throw InputError(where, "out of range (expected the largest coordinate " + std::string(kMagnitudeRange) + ")");
    }
    return v;
}

}  // namespace

Vec2 checked_vector(const Vec2& v, const std::string& where) { return checked(v, where); }

Vec3 checked_vector(const Vec3& v, const std::string& where) { return checked(v, where); }

Vec2 checked_direction(const Vec2& d, const std::string& where) {
    if (checked(d, where) == Vec2::Zero()) throw InputError(where, "the direction must not be zero");
    return d;
}

double checked_coefficient(double mu, const std::string& where) {
    if (!(mu >= 0.0) || !std::isfinite(mu) || !magnitude_in_range(mu)) {
        throw InputError(where, "expected a finite mu >= 0, " + std::string(kMagnitudeRange));
    }
    return mu;
}

Rational checked_coefficient(const Rational& mu, const std::string& where) {
    if (mu.sign() == Sign::Negative) (void)checked_coefficient(-1.0, where);
    (void)checked_coefficient(mu.to_double(), where);
    return mu;
}

double checked_length(double x, const std::string& where) {
    if (!(x > 0.0) || !std::isfinite(x) || !magnitude_in_range(x)) {
        throw InputError(where, "expected a length > 0, of magnitude " + std::string(kMagnitudeBounds));
    }
    return x;
}

Box checked_view(double xmin, double ymin, double xmax, double ymax, const std::string& where) {
    const bool finite = std::isfinite(xmin) && std::isfinite(ymin) && std::isfinite(xmax) && std::isfinite(ymax);
    if (!finite || !(xmin < xmax) || !(ymin < ymax) || !magnitude_in_range(std::max(xmax - xmin, ymax - ymin))) {
        throw InputError(where, "expected finite XMIN YMIN XMAX YMAX with XMIN < XMAX and YMIN < YMAX");
    }
    return Box{Vec2(xmin, ymin), Vec2(xmax, ymax)};
}

}  // namespace momentlab
