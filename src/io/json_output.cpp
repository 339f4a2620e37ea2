#include "momentlab/io/json_output.hpp"

#include <cmath>

#include "momentlab/io/input_error.hpp"

namespace momentlab {
namespace {

nlohmann::json vec(const Vec3& v) { return {output_value(v.x()), output_value(v.y()), output_value(v.z())}; }
nlohmann::json vec(const Vec2& v) { return {output_value(v.x()), output_value(v.y())}; }

template <class T>
nlohmann::json list(const std::vector<T>& vs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& v : vs) {
        if constexpr (std::is_same_v<T, ExactVector>) {
            out.push_back(vec(v.value()));
        } else {
            out.push_back(vec(v));
        }
    }
    return out;
}

}  // namespace

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

}  // namespace momentlab
