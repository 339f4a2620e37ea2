// validate_lcp: momentlab's `query` against Siconos Numerics on seeded random (scene, wrench)
// pairs. Each pair is posed as the acceleration-level planar Coulomb LCP (coulomb_lcp.hpp,
// docs/validation.md) and solved by lexicographic Lemke and by enumeration of every
// complementary basis. Must hold, on every pair whose wrench is not within 1e-7 (relative) of
// a plane of some E_i:
//   - the mode of every LCP solution is one of query(e)'s modes;
//   - when query says unique, Lemke's and the enumeration's solutions all have that mode;
//   - every mode of query(e) that no enumerated solution shows is confirmed by an exact LP;
//   - the enumeration's walk finds as many solving bases as its multiple-solutions pass counts.
// Counted as well: the ambiguous pairs each side finds, the pairs on which the enumeration finds
// exactly query's modes, and Lemke's failures. Exit status 1 on any disagreement.
#include <algorithm>
#include <map>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "coulomb_lcp.hpp"
#include "mode_oracle.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "random_inputs.hpp"
#include "report.hpp"

namespace {

using namespace momentlab;
using validation::CoulombLcp;

using testing::Random;  // reference/random_inputs.hpp

// mu in [0, 2]: exactly 0 one time in ten, exactly 2 one time in twenty, else uniform.
double random_mu(Random& r) {
    const int k = r.integer(0, 19);
    if (k < 2) return 0.0;
    if (k == 2) return 2.0;
    return r.uniform(0, 2);
}

Vec2 direction(double angle) { return Vec2(std::cos(angle), std::sin(angle)); }

enum class Family { Ring, Below, Box, Rod, Random };
constexpr int kFamilies = 5;
const char* family_name(Family f) {
    switch (f) {
        case Family::Ring: return "ring";
        case Family::Below: return "below";
        case Family::Box: return "box";
        case Family::Rod: return "rod";
        default: return "random";
    }
}

// A body with n contacts (mu_kinetic = mu: the LCP has one coefficient per contact).
//   ring: points around the body, normals towards its centre give or take 0.5 rad;
//   below: the same on the lower half only (the body can lift off);
//   box: the corners of a box against a floor, a wall or both (axis-aligned normals: exactly
//        parallel contact lines, the degenerate case);
//   rod: a slender body (inertia 1-10% of m L^2) whose ends touch floors and walls at
//        random angles: with mu up to 2, Painleve's paradox (no consistent mode) and
//        ambiguity (several) both occur;
//   random: any points in [-1, 1]^2, any normals.
Scene random_scene(Random& r, int n, Family family) {
    Scene s;
    const double mass = r.uniform(0.5, 2);
    s.body = Body{mass, Vec2(r.uniform(-0.3, 0.3), r.uniform(-0.3, 0.3)), mass * r.uniform(0.05, 0.5), {}};
    const Vec2 centre = s.body->com;
    const double ax = r.uniform(0.5, 1.5), ay = r.uniform(0.5, 1.5);
    const double length = 2 * ax, tilt = r.uniform(0.1, M_PI - 0.1);  // for rods
    if (family == Family::Rod) s.body->inertia = mass * length * length * r.uniform(0.01, 0.1);
    for (int j = 0; j < n; ++j) {
        Vec2 p, normal;
        switch (family) {
            case Family::Ring:
            case Family::Below: {
                const double a = family == Family::Ring ? r.uniform(0, 2 * M_PI) : r.uniform(M_PI, 2 * M_PI);
                p = centre + Vec2(ax * std::cos(a), ay * std::sin(a));
                const Vec2 in = centre - p;
                normal = direction(std::atan2(in.y(), in.x()) + r.uniform(-0.5, 0.5));
                break;
            }
            case Family::Box: {
                // Corners (+-w, +-h); floor contacts at the bottom corners, wall contacts (x = -w)
                // at the left corners, roof contacts at the top.
                const double w = 0.5 * ax, h = 0.5 * ay;
                static const int kCorner[][4] = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, -1, 1, 0},
                                                 {-1, 1, 1, 0}, {-1, 1, 0, -1}, {1, 1, 0, -1}};
                const int* c = kCorner[r.integer(0, 5)];
                p = Vec2(c[0] * w, c[1] * h);
                normal = Vec2(c[2], c[3]);
                break;
            }
            case Family::Rod: {
                // A ladder: the lower end on a floor, the upper end against a wall on its
                // side, further contacts anywhere along it with any normal.
                const Vec2 along = direction(tilt);
                const double at = j == 0 ? -0.5 : (j == 1 ? 0.5 : r.uniform(-0.5, 0.5));
                p = centre + at * length * along;
                normal = j == 0 ? Vec2(0, 1) : (j == 1 ? Vec2(along.x() > 0 ? -1 : 1, 0)
                                                       : direction(r.uniform(0, 2 * M_PI)));
                break;
            }
            case Family::Random:
                p = Vec2(r.uniform(-1, 1), r.uniform(-1, 1));
                normal = direction(r.uniform(0, 2 * M_PI));
                break;
        }
        const double mu = random_mu(r);
        s.contacts.push_back(Contact::make(p, normal, mu, mu));
    }
    return s;
}

// The smallest |f . e| / (|f| |e|) over the facet planes of every E_i: how far (in angle) the
// wrench is from a boundary between modes. Conservative: a plane is a boundary only near its facet.
double margin(const std::vector<ModeForces>& analysis, const Vec3& e) {
    double m = 1.0;
    for (const ModeForces& mf : analysis) {
        for (const ExactVector& f : mf.applied.facets()) {
            const Vec3& v = f.value();
            m = std::min(m, std::abs(v.dot(e)) / (v.norm() * e.norm()));
        }
        // A lower-dimensional E_i: within it along its equations.
        for (const ExactVector& f : mf.applied.equations()) {
            const Vec3& v = f.value();
            m = std::min(m, std::abs(v.dot(e)) / (v.norm() * e.norm()));
        }
    }
    return m;
}

std::string describe(const Scene& s, const Vec3& e) {
    std::ostringstream out;
    out.precision(17);
    out << "  e = (" << e.x() << ", " << e.y() << ", " << e.z() << ")\n  body m=" << s.body->mass << " com=("
        << s.body->com.x() << ", " << s.body->com.y() << ") I=" << s.body->inertia << "\n";
    for (const Contact& c : s.contacts) {
        out << "  contact p=(" << c.point.x() << ", " << c.point.y() << ") n=(" << c.normal.x() << ", "
            << c.normal.y() << ") mu=" << c.mu << "\n";
    }
    return out.str();
}

std::string join(const std::set<std::string>& modes) {
    std::string s;
    for (const std::string& m : modes) s += (s.empty() ? "" : ",") + m;
    return s.empty() ? "-" : s;
}

struct Tally {
    long pairs = 0, near = 0;
    long unique = 0, ambiguous = 0, inconsistent = 0;           // query's verdicts
    long lemke_solved = 0, lemke_in_query = 0;                  // Lemke's solutions, and in query
    long lemke_failed_with_modes = 0;                           // Lemke found none, query has modes
    long lemke_inaccurate = 0;                                  // Lemke returned, residual > 1e-8
    long rejected = 0;                                          // enumerated bases with residual > 1e-8
    long unique_checked = 0, unique_agree = 0;                  // query unique: LCP says the same
    long enumerated = 0, solutions = 0, solutions_in_query = 0; // enumeration's solutions
    long enum_ambiguous = 0, enum_unique = 0, enum_none = 0;    // distinct modes the LCP finds
    long enum_same_set = 0;                                     // exactly query's modes
    long enum_query_ambiguous = 0;                              // query ambiguous, among those pairs
    long missed = 0, missed_confirmed = 0;                      // query's modes the enumeration lacks
    double worst_residual = 0;
};

}  // namespace

int main(int argc, char** argv) {
    const validation::Options opt(argc, argv, {{"pairs", "10000"}, {"seed", "20261121"},
                                               {"enumerate", "2:1,3:1,4:10"}, {"markdown", ""},
                                               {"verbose", "0"}, {"lemke", "lexico"}});
    const long pairs = opt.integer("pairs");
    // Which pairs are enumerated, as contacts:every; "4:10" is every tenth pair with 4 contacts.
    // An enumeration tries 2^(4n) bases twice: n = 4 takes 0.2 s here, 5 about 6 s, 6 about 90 s.
    std::map<int, long> every;
    {
        std::istringstream in(opt.text("enumerate"));
        std::string item;
        while (std::getline(in, item, ',')) {
            const auto colon = item.find(':');
            if (colon == std::string::npos) throw std::invalid_argument("--enumerate: contacts:every, comma separated");
            every[std::stoi(item.substr(0, colon))] = std::stol(item.substr(colon + 1));
        }
    }
    std::map<int, long> seen;  // pairs so far per number of contacts
    const bool verbose = opt.integer("verbose") != 0;
    // lexico: lcp_lexicolemke (Siconos' Lemke); pivot: lcp_pivot with Lemke's rule.
    const bool pivot = opt.text("lemke") == "pivot";
    Random r(static_cast<std::uint64_t>(opt.integer("seed")));
    Tally t;
    long failures = 0;
    auto fail = [&](long i, const Scene& s, const Vec3& e, const std::string& what) {
        ++failures;
        if (failures <= 20) std::fprintf(stderr, "pair %ld: %s\n%s", i, what.c_str(), describe(s, e).c_str());
    };

    for (long i = 0; i < pairs; ++i) {
        const int n = 2 + static_cast<int>(i % 5);
        const auto family = static_cast<Family>((i / 5) % kFamilies);
        const Scene scene = random_scene(r, n, family);
        const Vec3 e(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
        ++t.pairs;

        const std::vector<ModeForces> analysis = analyze(scene);
        const QueryResult answer = query(analysis, e);
        std::set<std::string> expected;
        for (std::size_t k : answer.modes) expected.insert(analysis[k].mode.letters);
        if (margin(analysis, e) < 1e-7) {
            ++t.near;
            continue;
        }
        t.unique += answer.verdict == Verdict::Unique;
        t.ambiguous += answer.verdict == Verdict::Ambiguous;
        t.inconsistent += answer.verdict == Verdict::Inconsistent;

        CoulombLcp lcp(scene);
        validation::LcpSolution solution;
        const bool returned = pivot ? lcp.lemke_pivot(e, solution) : lcp.lemke(e, solution);
        const bool solved = returned && lcp.solves(e, solution);
        t.lemke_inaccurate += returned && !solved;
        if (verbose && returned && !solved) {
            std::fprintf(stderr, "pair %ld (%s, n=%d): Lemke's residual %.2e, max z %.2e, query %s\n", i,
                         family_name(family), n, lcp.residual(e, solution), solution.z.cwiseAbs().maxCoeff(),
                         join(expected).c_str());
        }
        std::string lemke_mode;
        if (solved) {
            ++t.lemke_solved;
            t.worst_residual = std::max(t.worst_residual, lcp.residual(e, solution));
            lemke_mode = lcp.mode(e, solution);
            if (expected.count(lemke_mode)) ++t.lemke_in_query;
            else fail(i, scene, e, "Lemke's mode " + lemke_mode + " is not among query's " + join(expected));
        } else if (!expected.empty()) {
            ++t.lemke_failed_with_modes;
        }

        std::set<std::string> found;
        const long k = seen[n]++;
        const bool enumerate = every.count(n) && every[n] > 0 && k % every[n] == 0;
        if (enumerate) {
            ++t.enumerated;
            const validation::LcpEnumeration all = lcp.enumerate(e);
            if (static_cast<int>(all.solutions.size()) != all.counted) {
                fail(i, scene, e, "the walk found " + std::to_string(all.solutions.size()) +
                                      " solving bases, the multiple-solutions pass " + std::to_string(all.counted));
            }
            for (const validation::LcpSolution& s : all.solutions) {
                if (!lcp.solves(e, s)) {
                    if (verbose) {
                        std::fprintf(stderr, "pair %ld basis %ld rejected: %s residual %.2e max z %.2e\n", i,
                                     (long)s.basis, lcp.mode(e, s).c_str(), lcp.residual(e, s), s.z.cwiseAbs().maxCoeff());
                    }
                    ++t.rejected;  // a near-singular basis: entries near 1e16 that solve nothing
                    continue;
                }
                ++t.solutions;
                t.worst_residual = std::max(t.worst_residual, lcp.residual(e, s));
                const std::string m = lcp.mode(e, s);
                found.insert(m);
                if (expected.count(m)) ++t.solutions_in_query;
                else fail(i, scene, e, "enumerated mode " + m + " is not among query's " + join(expected));
            }
            t.enum_ambiguous += found.size() > 1;
            t.enum_unique += found.size() == 1;
            t.enum_none += found.empty();
            t.enum_same_set += found == expected;
            t.enum_query_ambiguous += expected.size() > 1;
            // A mode query has and no basic solution shows: ask the exact LP.
            for (const std::string& m : expected) {
                if (found.count(m)) continue;
                ++t.missed;
                if (testing::exact_lp_applied_in_mode(scene, m, e)) ++t.missed_confirmed;
                else fail(i, scene, e, "query's mode " + m + " is neither enumerated nor confirmed by the exact LP");
            }
            if (verbose && found != expected) {
                std::fprintf(stderr, "pair %ld (%s, n=%d): query %s, enumeration %s\n%s", i, family_name(family), n,
                             join(expected).c_str(), join(found).c_str(), describe(scene, e).c_str());
            }
        }
        if (answer.verdict == Verdict::Unique) {
            ++t.unique_checked;
            const std::string& m = *expected.begin();
            const bool lemke_ok = !solved || lemke_mode == m;
            const bool enum_ok = !enumerate || found == expected;
            if (lemke_ok && enum_ok) ++t.unique_agree;
            else fail(i, scene, e, "query: unique " + m + "; Lemke " + (solved ? lemke_mode : "-") +
                                       ", enumeration " + (enumerate ? join(found) : "(not run)"));
        }
        if (pairs >= 1000 && (i + 1) % (pairs / 10) == 0) {
            std::fprintf(stderr, "validate_lcp: %ld / %ld pairs\n", i + 1, pairs);
        }
    }

    std::printf("validate_lcp: %ld pairs (2-6 contacts, mu in [0, 2]), %ld within 1e-7 of a mode boundary left out\n",
                t.pairs, t.near);
    std::printf("  query: %ld unique, %ld ambiguous, %ld inconsistent\n", t.unique, t.ambiguous, t.inconsistent);
    std::printf("  Lemke: %ld solved; %ld failed where query has modes (%ld of them returned an inaccurate solution)\n",
                t.lemke_solved, t.lemke_failed_with_modes, t.lemke_inaccurate);
    std::printf("  enumeration (%s): %ld pairs (query: %ld ambiguous), %ld solutions; modes found: %ld ambiguous, %ld unique, "
                "%ld none; exactly query's modes on %ld; bases rejected by the residual %ld\n",
                opt.text("enumerate").c_str(), t.enumerated, t.enum_query_ambiguous, t.solutions, t.enum_ambiguous, t.enum_unique, t.enum_none,
                t.enum_same_set, t.rejected);
    std::printf("  query's modes without a basic LCP solution: %ld, of which the exact LP (cddlib) confirms %ld\n",
                t.missed, t.missed_confirmed);
    std::printf("  worst residual of an accepted solution %.1e\n", t.worst_residual);

    std::ostringstream a, b, c, d;
    a << t.pairs << " pairs, " << t.near << " near a boundary left out; query: " << t.unique << " unique, "
      << t.ambiguous << " ambiguous, " << t.inconsistent << " inconsistent";
    b << "no solution from Lemke on " << t.lemke_failed_with_modes << " pairs that have modes (on "
      << t.lemke_inaccurate << " it reported success with a vector off the LCP by > 1e-8)";
    c << t.enumerated << " pairs (" << opt.text("enumerate") << " as contacts:every); ambiguous: query "
      << t.enum_query_ambiguous << ", LCP " << t.enum_ambiguous << "; the same modes on " << t.enum_same_set;
    d << "modes of query that no basic LCP solution shows (singular bases, e.g. a squeeze)";
    std::vector<validation::Row> rows{
        {"Siconos Lemke", "Lemke's solution has one of query(e)'s modes", t.lemke_solved, t.lemke_in_query, b.str()},
        {"Siconos enumeration", "every LCP solution has one of query(e)'s modes", t.solutions, t.solutions_in_query,
         c.str()},
        {"Siconos", "query unique: every LCP solution has that mode", t.unique_checked, t.unique_agree, a.str()},
        {"cddlib exact LP", "e is in E_i for the modes the enumeration misses", t.missed, t.missed_confirmed, d.str()},
    };
    validation::write_rows(rows, opt.text("markdown"));
    if (failures > 0) std::fprintf(stderr, "validate_lcp: %ld disagreements\n", failures);
    return failures > 0 ? 1 : 0;
}
