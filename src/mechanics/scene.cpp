#include "momentlab/mechanics/scene.hpp"

#include <cmath>
#include <stdexcept>

#include "contact_model.hpp"

namespace momentlab {
namespace {

void check_contact(const Vec2& point, const Vec2& normal, double mu, double mu_kinetic) {
    if (!point.allFinite()) throw std::invalid_argument("contact point must be finite");
    if (!normal.allFinite() || (normal.x() == 0.0 && normal.y() == 0.0)) {
        throw std::invalid_argument("contact normal must be finite and non-zero");
    }
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("mu must be finite and >= 0");
    if (!(mu_kinetic >= 0.0) || !std::isfinite(mu_kinetic)) throw std::invalid_argument("mu_kinetic must be finite and >= 0");
}

}  // namespace

Contact Contact::make(const Vec2& point, const Vec2& normal, double mu, std::optional<double> mu_kinetic, std::string name) {
    const double mk = mu_kinetic.value_or(mu);
    check_contact(point, normal, mu, mk);
    Contact c;
    c.point = point;
    c.normal = normal;
    c.mu = mu;
    c.mu_kinetic = mk;
    c.name = std::move(name);
    return c;
}

Contact Contact::make(const Rational2& point, const Rational2& normal, const Rational& mu,
                      const std::optional<Rational>& mu_kinetic, std::string name) {
    ContactValues v;
    v.point = point;
    v.normal = normal;
    v.mu = mu;
    v.mu_kinetic = mu_kinetic.value_or(mu);
    v.point_double = to_double(point);
    v.normal_double = to_double(normal);
    v.mu_double = mu.to_double();
    v.mu_kinetic_double = v.mu_kinetic.to_double();
    return make(std::move(v), std::move(name));
}

Contact Contact::make(ContactValues v, std::string name) {
    // The exact signs: a normal of tiny decimals is not zero, a mu below 2^-1074 not negative.
    if (v.normal[0].is_zero() && v.normal[1].is_zero()) throw std::invalid_argument("contact normal must be finite and non-zero");
    if (v.mu.sign() == Sign::Negative) throw std::invalid_argument("mu must be finite and >= 0");
    if (v.mu_kinetic.sign() == Sign::Negative) throw std::invalid_argument("mu_kinetic must be finite and >= 0");
    Contact c = make(v.point_double, v.normal_double, v.mu_double, v.mu_kinetic_double, std::move(name));
    if (!is_double(v.point) || !is_double(v.normal) || !v.mu.is_double() || !v.mu_kinetic.is_double()) {
        c.exact = std::make_shared<const ContactValues>(std::move(v));
    }
    return c;
}

const ContactValues* Contact::exact_values() const {
    if (!exact) return nullptr;
    const ContactValues& v = *exact;
    const bool current = v.point_double == point && v.normal_double == normal && v.mu_double == mu && v.mu_kinetic_double == mu_kinetic;
    return current ? &v : nullptr;
}

bool Contact::kinetic_is_static() const {
    const ContactValues* v = exact_values();
    return v ? v->mu == v->mu_kinetic : mu == mu_kinetic;
}

ExactVector Contact::normal_wrench() const {
    const ContactValues* v = exact_values();
    if (!v) return ExactVector::wrench(point, normal);
    const detail::ClearedContact c = detail::cleared(*v);
    return ExactVector::from_exact(detail::cleared_wrench(c, c.normal));
}

ExactVector Contact::tangent_wrench() const {
    const ContactValues* v = exact_values();
    if (!v) return ExactVector::wrench(point, tangent());
    const detail::ClearedContact c = detail::cleared(*v);
    return ExactVector::from_exact(detail::cleared_wrench(c, Exact2{c.normal[1], -c.normal[0]}));
}

std::array<ExactVector, 2> Contact::friction_edges(bool kinetic) const {
    const ContactValues* v = exact_values();
    if (!v) return friction_cone_edges(point, normal, kinetic ? mu_kinetic : mu);
    using detail::FrictionEdge;
    const detail::ClearedContact c = detail::cleared(*v);
    const auto edge = [&](FrictionEdge e) { return ExactVector::from_exact(detail::cleared_wrench(c, detail::edge_direction(c, e))); };
    if (kinetic) return {edge(FrictionEdge::KineticPlus), edge(FrictionEdge::KineticMinus)};
    return {edge(FrictionEdge::StaticPlus), edge(FrictionEdge::StaticMinus)};
}

const BodyValues* Body::exact_values() const {
    if (!exact) return nullptr;
    const BodyValues& v = *exact;
    const bool current = v.mass_double == mass && v.com_double == com && v.inertia_double == inertia && v.radius_double == radius_of_gyration;
    return current ? &v : nullptr;
}

Rational2 Body::exact_com() const {
    const BodyValues* v = exact_values();
    return v ? v->com : rational(com);
}

std::vector<Rational2> Body::exact_polygon() const {
    const BodyValues* v = exact_values();
    bool typed = v && v->polygon.size() == polygon.size();
    for (std::size_t i = 0; typed && i < polygon.size(); ++i) typed = to_double(v->polygon[i]) == polygon[i];  // not edited since
    if (typed) return v->polygon;
    std::vector<Rational2> out;
    out.reserve(polygon.size());
    for (const Vec2& p : polygon) out.push_back(rational(p));
    return out;
}

ExactMatrix inertia_at_origin(const Body& body) {
    if (const BodyValues* v = body.exact_values()) return detail::cleared_inertia(*v);
    return detail::body_inertia<Dyadic>(body, [](double x) { return Dyadic(x); });
}

namespace detail {

ClearedContact cleared(const ContactValues& values) {
    ClearedContact c;
    const std::vector<Dyadic> p = clear_denominators(values.point, &c.scale);
    c.point = {p[0], p[1]};
    const std::vector<Dyadic> n = clear_denominators(values.normal);
    c.normal = {n[0], n[1]};
    const auto ratio = [](const Rational& mu, Dyadic& num, Dyadic& den) {
        const std::vector<Dyadic> a = clear_denominators(std::span<const Rational>(&mu, 1), &den);
        num = a[0];
    };
    ratio(values.mu, c.mu_num, c.mu_den);
    ratio(values.mu_kinetic, c.kinetic_num, c.kinetic_den);
    return c;
}

Exact2 edge_direction(const ClearedContact& c, FrictionEdge e) {
    const bool kinetic = e == FrictionEdge::KineticPlus || e == FrictionEdge::KineticMinus;
    const bool plus = e == FrictionEdge::StaticPlus || e == FrictionEdge::KineticPlus;
    const Dyadic& den = kinetic ? c.kinetic_den : c.mu_den;
    const Dyadic num = plus ? (kinetic ? c.kinetic_num : c.mu_num) : -(kinetic ? c.kinetic_num : c.mu_num);
    return friction_direction(c.normal[0], c.normal[1], num, &den);
}

Exact3 cleared_wrench(const ClearedContact& c, const Exact2& d) { return {c.scale * d[0], c.scale * d[1], cross2(c.point, d)}; }

std::array<Exact3, 3> cleared_inertia(const BodyValues& v) {
    const Rational &m = v.mass, &cx = v.com[0], &cy = v.com[1];
    const Rational ic = v.radius_of_gyration ? m * *v.radius_of_gyration * *v.radius_of_gyration : v.inertia;
    const auto matrix = inertia_matrix(m, cx, cy, ic);
    std::array<Rational, 9> entries;
    for (std::size_t i = 0; i < entries.size(); ++i) entries[i] = matrix[i / 3][i % 3];
    const std::vector<Dyadic> e = clear_denominators(entries);
    return {Exact3{e[0], e[1], e[2]}, Exact3{e[3], e[4], e[5]}, Exact3{e[6], e[7], e[8]}};
}

}  // namespace detail
}  // namespace momentlab
