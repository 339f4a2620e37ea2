// validate_cdd: the cone kernel against cddlib (Komei Fukuda) in exact GMP rational mode, on
// seeded random cones of every family of reference/random_inputs.hpp: general doubles,
// doubles in a half-space, and exactly degenerate small-integer sets (coplanar, collinear,
// antipodal, pure moments, mixed repeats). Each input is built both ways, as the cone its
// vectors generate and as the cone of their half-spaces, and must agree with cddlib's minimal
// representation: dimension, lineality, the number of extreme rays and facets, and which input
// vectors lie on which facet (reference/cone_checks.hpp). Exit status 1 on a disagreement.
#include <cstdio>
#include <map>
#include <sstream>

#include "cone_checks.hpp"
#include "random_inputs.hpp"
#include "report.hpp"

int main(int argc, char** argv) {
    using namespace momentlab;
    const validation::Options opt(argc, argv, {{"cones", "10000"}, {"seed", "20261121"}, {"markdown", ""}});
    const long cones = opt.integer("cones");
    testing::Random rnd(static_cast<std::uint64_t>(opt.integer("seed")));
    static const testing::Family kFamilies[] = {
        testing::Family::GeneralDoubles, testing::Family::HalfSpaceDoubles, testing::Family::SmallIntegers,
        testing::Family::Coplanar,       testing::Family::Collinear,        testing::Family::Antipodal,
        testing::Family::PureMoments,    testing::Family::Mixed};
    long cases = 0, agree = 0, degenerate = 0;
    std::map<std::string, long> kinds;
    for (long i = 0; i < cones; ++i) {
        const testing::Family family = kFamilies[i % 8];
        const std::vector<Vec3> v = testing::random_generators(rnd, family, 8);
        degenerate += testing::is_integral(family);
        for (const Representation primary : {Representation::Generators, Representation::Halfspaces}) {
            const bool generators = primary == Representation::Generators;
            const Cone ours = generators ? Cone::from_generators(v) : Cone::from_halfspaces(v);
            const oracle::OracleCone theirs = generators ? oracle::from_generators(v) : oracle::from_halfspaces(v);
            ++cases;
            ++kinds[ours.kind()];
            const std::string why = testing::compare_with_oracle(ours, theirs);
            if (why.empty()) {
                ++agree;
            } else if (cases - agree <= 20) {
                std::fprintf(stderr, "%s from %s %s: %s\n", generators ? "cone" : "half-spaces",
                             testing::family_name(family), testing::describe(v).c_str(), why.c_str());
            }
        }
    }
    std::printf("validate_cdd: %ld inputs (%ld exactly degenerate), each as generators and as half-spaces: "
                "%ld of %ld cones agree with cddlib (GMP)\n", cones, degenerate, agree, cases);
    std::printf("  kinds:");
    std::ostringstream k;
    for (const auto& [kind, n] : kinds) {
        std::printf(" %s %ld;", kind.c_str(), n);
        k << (k.str().empty() ? "" : ", ") << kind << " " << n;
    }
    std::printf("\n");
    std::ostringstream notes;
    notes << cones << " inputs, " << degenerate << " exactly degenerate; kinds: " << k.str();
    validation::write_rows({{"cddlib (GMP)", "facets, extreme rays, lineality and incidences of each cone", cases,
                             agree, notes.str()}},
                           opt.text("markdown"));
    return agree == cases ? 0 : 1;
}
