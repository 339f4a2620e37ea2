#include "momentlab/mechanics/scene.hpp"

#include <cmath>
#include <stdexcept>

#include "contact_model.hpp"

namespace momentlab {

Contact Contact::make(const Vec2& point, const Vec2& normal, double mu,
                      std::optional<double> mu_kinetic, std::string name) {
    if (!point.allFinite()) throw std::invalid_argument("contact point must be finite");
    if (!normal.allFinite() || (normal.x() == 0.0 && normal.y() == 0.0)) {
        throw std::invalid_argument("contact normal must be finite and non-zero");
    }
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("mu must be finite and >= 0");
    const double mk = mu_kinetic.value_or(mu);
    if (!(mk >= 0.0) || !std::isfinite(mk)) throw std::invalid_argument("mu_kinetic must be finite and >= 0");
    Contact c;
    c.point = point;
    c.normal = normal;
    c.mu = mu;
    c.mu_kinetic = mk;
    c.name = std::move(name);
    return c;
}

ExactVector Contact::normal_wrench() const { return ExactVector::wrench(point, normal); }

ExactVector Contact::tangent_wrench() const { return ExactVector::wrench(point, tangent()); }

ExactMatrix inertia_at_origin(const Body& body) { return detail::inertia_matrix<Dyadic>(body); }

}  // namespace momentlab
