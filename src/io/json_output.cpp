#include "momentlab/io/json_output.hpp"

#include <cmath>

#include <boost/multiprecision/cpp_int.hpp>

#include "momentlab/io/input_error.hpp"

namespace momentlab {
namespace {

using BigInteger = boost::multiprecision::cpp_int;

// x = m 2^e as m and e (m an integer: its limbs).
BigInteger integer_part(const Dyadic& x) {
    BigInteger m = 0;
    const auto limbs = x.limbs();
    for (std::size_t i = limbs.size(); i-- > 0;) m = (m << 64) | BigInteger(limbs[i]);
    return x.sign() == Sign::Negative ? BigInteger(-m) : m;
}

template <class T>
nlohmann::json list(const std::vector<T>& vs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& v : vs) {
        if constexpr (std::is_same_v<T, ExactVector>) {
            out.push_back(vector_json(v.value()));
        } else {
            out.push_back(vector_json(v));
        }
    }
    return out;
}

}  // namespace

nlohmann::json vector_json(const Vec3& v) { return {output_value(v.x()), output_value(v.y()), output_value(v.z())}; }
nlohmann::json vector_json(const Vec2& v) { return {output_value(v.x()), output_value(v.y())}; }

nlohmann::json to_json(const Cone& cone) {
    nlohmann::json incidence = nlohmann::json::array();
    for (std::size_t j = 0; j < cone.facet_rays().size(); ++j) {
        const auto row = cone.facet_rays().row(j);
        incidence.push_back(std::vector<int>(row.begin(), row.end()));
    }
    return {{"kind", cone.kind()},
            {"dimension", cone.dimension()},
            {"lineality_dimension", cone.lineality_dimension()},
            {"rays", list(cone.rays())},
            {"lineality", list(cone.lineality())},
            {"facets", list(cone.facets())},
            {"equations", list(cone.equations())},
            {"facet_rays", incidence}};
}

nlohmann::json to_json(const Region& region) {
    return {{"kind", region.kind()},
            {"vertices", list(region.vertices)},
            {"rays", list(region.rays)},
            {"lines", list(region.lines)}};
}

nlohmann::json to_json(const Labels& labels) {
    return {{"plus", to_json(labels.plus())}, {"minus", to_json(labels.minus())}};
}


namespace {

nlohmann::json intervals_json(const std::vector<AngleInterval>& intervals) {
    nlohmann::json out = nlohmann::json::array();
    for (const AngleInterval& i : intervals) out.push_back({output_value(i.from), output_value(i.to)});
    return out;
}

nlohmann::json distance_json(double d) { return std::isfinite(d) ? nlohmann::json(output_value(d)) : nlohmann::json("unbounded"); }

}  // namespace

namespace {

// "<key>_exact": the exact magnitude as text, when it is not the double printed.
void add_exact(nlohmann::json& out, const char* key, const Magnitude& m) {
    if (!(m.num == Dyadic(m.value()) * m.den)) out[std::string(key) + "_exact"] = exact_text(m.num, m.den);
}

}  // namespace

nlohmann::json to_json(const MagnitudeRange& range) {
    nlohmann::json out = {{"from", output_value(range.lo.value())},
                          {"to", range.hi ? nlohmann::json(output_value(range.hi->value())) : nlohmann::json("unbounded")}};
    add_exact(out, "from", range.lo);
    if (range.hi) add_exact(out, "to", *range.hi);
    return out;
}

nlohmann::json to_json(const QueryMargins& margins) {
    nlohmann::json inside = nlohmann::json::array();
    for (double d : margins.inside) inside.push_back(distance_json(d));
    return {{"inside", inside}, {"to_other", margins.to_other ? distance_json(*margins.to_other) : nlohmann::json("unbounded")}};
}

nlohmann::json to_json(const std::vector<MagnitudeBand>& bands, std::span<const ModeForces> analysis) {
    nlohmann::json out = nlohmann::json::array();
    for (const MagnitudeBand& b : bands) {
        nlohmann::json modes = nlohmann::json::array();
        for (std::size_t j : b.modes) modes.push_back(analysis[j].mode.letters);
        out.push_back({{"from", output_value(b.from.value())},
                       {"to", b.to ? nlohmann::json(output_value(b.to->value())) : nlohmann::json("unbounded")},
                       {"from_closed", b.from_closed},
                       {"to_closed", b.to_closed},
                       {"modes", modes},
                       {"verdict", to_string(verdict_of(b.modes.size()))}});
        add_exact(out.back(), "from", b.from);
        if (b.to) add_exact(out.back(), "to", *b.to);
    }
    return out;
}

void add_exact(nlohmann::json& out, const std::string& key, std::span<const Rational> values) {
    if (is_double(values)) return;
    nlohmann::json texts = nlohmann::json::array();
    for (const Rational& v : values) texts.push_back(exact_text(v.num(), v.den()));
    out[key + "_exact"] = values.size() == 1 ? texts[0] : texts;
}

std::string exact_text(const Dyadic& num, const Dyadic& den) {
    BigInteger p = integer_part(num), q = integer_part(den);
    const std::int64_t e = num.binary_exponent() - den.binary_exponent();  // num / den = p / q 2^e
    if (e > 0) p <<= static_cast<unsigned>(e);
    if (e < 0) q <<= static_cast<unsigned>(-e);
    if (q < 0) p = -p, q = -q;
    const BigInteger g = boost::multiprecision::gcd(p, q);
    if (g > 1) p /= g, q /= g;
    return q == 1 ? p.str() : p.str() + "/" + q.str();
}

nlohmann::json to_json(const DirectionPlan& plan) {
    nlohmann::json out = {{"intervals", intervals_json(plan.intervals)}};
    if (plan.feasible()) {
        out["best"] = output_value(plan.best);
        out["margin"] = output_value(plan.margin);
        out["knife_edge"] = plan.knife_edge;
        if (plan.uniqueness_known) {
            out["unique"] = intervals_json(plan.unique);
            out["shared"] = intervals_json(plan.shared);
            out["best_unique"] = plan.best_unique;
        }
        if (plan.best_margins) out["best_margins"] = to_json(*plan.best_margins);
        if (plan.magnitudes_known) out["best_magnitudes"] = plan.best_magnitudes ? to_json(*plan.best_magnitudes) : nlohmann::json();
    }
    return out;
}

nlohmann::json to_json(const PushCase& c) {
    nlohmann::json touch = nlohmann::json::array();
    for (const auto& [p, q] : c.touch) touch.push_back({vector_json(p), vector_json(q)});
    nlohmann::json out = {{"feature", c.feature.name()},
                          {"from", vector_json(c.feature.from)},
                          {"to", vector_json(c.feature.to)},
                          {"slip", std::string(1, letter(c.slip))},
                          {"verdict", to_string(c.verdict)},
                          {"feasible", c.feasible()},
                          {"blocked", c.blocked},
                          {"touch", touch}};
    out["directions"] = c.directions ? nlohmann::json{output_value(c.directions->from), output_value(c.directions->to)}
                                     : nlohmann::json();
    if (c.best) {
        // The push measured (its magnitudes, margins and uniqueness) is the point and the unit vector
        // exactly; the angle is rounded from it.
        out["best"] = {{"point", vector_json(c.best->point)},
                       {"direction", output_value(std::atan2(c.best->direction.y(), c.best->direction.x()))},
                       {"direction_vector", vector_json(c.best->direction)}};
    }
    if (c.uniqueness_known) {
        out["unique"] = c.unique;
        out["shared"] = c.shared;
        out["best_unique"] = c.best_unique;
        nlohmann::json unique_touch = nlohmann::json::array();
        for (const auto& [p, q] : c.unique_touch) unique_touch.push_back({vector_json(p), vector_json(q)});
        out["unique_touch"] = unique_touch;
        out["unique_directions"] = c.unique_directions ? nlohmann::json{output_value(c.unique_directions->from),
                                                                         output_value(c.unique_directions->to)}
                                                       : nlohmann::json();
    }
    if (c.best_margins) out["best_margins"] = to_json(*c.best_margins);
    if (c.magnitudes_known && c.best) out["best_magnitudes"] = c.best_magnitudes ? to_json(*c.best_magnitudes) : nlohmann::json();
    return out;
}

nlohmann::json to_json(const ComplyPlan& plan) {
    nlohmann::json out = to_json(plan.directions);
    out["point"] = vector_json(plan.centre);
    out["label"] = to_string(plan.label);
    out["verdict"] = to_string(plan.verdict);
    return out;
}

namespace {

nlohmann::json closure_test_json(const ClosureTest& t) {
    nlohmann::json out = {{"holds", t.holds}};
    if (t.holds) {
        out["quality"] = output_value(t.quality);
    } else {
        out["unresisted_wrench"] = vector_json(t.unresisted->value());
    }
    return out;
}

}  // namespace

nlohmann::json to_json(const Closure& c) {
    return {{"form_closure", c.form.holds},
            {"force_closure", c.force.holds},
            {"form", closure_test_json(c.form)},
            {"force", closure_test_json(c.force)},
            {"reference", vector_json(c.reference)},
            {"length", output_value(c.length)},
            {"metric", kClosureQualityMetric}};
}

}  // namespace momentlab
