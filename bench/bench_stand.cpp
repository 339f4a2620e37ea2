// Assemblies (docs/assemblies.md): can_stand, equilibrium(), on masonry arches and brick walls,
// side by side in the same run with GLPK 5's floating-point simplex (glp_simplex) and its exact
// rational simplex (glp_exact) on the same linear program built for the same scene: a column per
// friction-cone edge (+w on body a's three rows, -w on body b's), three rows per body, the
// right-hand side minus the gravity wrenches, every column >= 0, no objective. GLPK's problem
// is built outside the timed loop (and timed on its own, BM_glpk_build); each timed solve starts
// from the standard basis (glp_std_basis), with the problem scaled once (glp_scale_prob,
// GLP_SF_AUTO) and presolving off. Ours is the whole call: the program built from the scene in
// interval arithmetic, the double simplex, its certificate, the exact simplex when needed.
// Then the mode enumeration (assembly_modes) on towers, small walls and arches of 2-4 bodies
// and up to 12 contacts.
#include <benchmark/benchmark.h>
#include <glpk.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "assembly/linear_program.hpp"
#include "assembly_scenes.hpp"
#include "momentlab/assembly/stand.hpp"

namespace {

using namespace momentlab;
using namespace momentlab::assembly_scenes;

// The scenes of the equilibrium table: (family, size).
enum Family { kArch = 0, kThinArch = 1, kWall = 2, kTiltedWall = 3 };
const char* const kFamilyNames[] = {"arch (stands)", "thin arch (falls)", "wall, upright", "wall, tilted 1/8"};

// Gravity as the double (0, -9.81) (GLPK's program and ours from the same numbers).
const Vec2 kGravity(0.0, -9.81);

struct Case {
    Assembly assembly;
    Vec2 gravity;
};

Case scene(int family, int size) {
    switch (family) {
        case kArch: return {without_polygons(semicircular_arch(size, 0.15, 0.6)), kGravity};
        case kThinArch: return {without_polygons(semicircular_arch(size, 0.05, 0.6)), kGravity};
        case kWall: return {without_polygons(running_bond_wall(size, 5, 0.6)), kGravity};
        default: return {without_polygons(running_bond_wall(size, 5, 0.6)), Vec2(9.81 / 8, -9.81)};
    }
}

// The program in GLPK, from the scene's numbers in doubles (the products rounded once; for the
// walls, whose numbers are small integers, exactly the program ours decides).
glp_prob* glpk_equilibrium(const Assembly& a, const Vec2& g) {
    glp_prob* p = glp_create_prob();
    glp_set_obj_dir(p, GLP_MIN);
    glp_add_rows(p, static_cast<int>(3 * a.bodies.size()));
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
        const AssemblyBody& b = a.bodies[k];
        const double gravity[3] = {b.mass * g.x(), b.mass * g.y(), b.com.x() * b.mass * g.y() - b.com.y() * b.mass * g.x()};
        for (int r = 0; r < 3; ++r) glp_set_row_bnds(p, static_cast<int>(3 * k) + r + 1, GLP_FX, -gravity[r], -gravity[r]);
    }
    std::vector<int> ia{0}, ja{0};
    std::vector<double> ar{0.0};
    for (const AssemblyContact& ac : a.contacts) {
        const Contact& c = ac.contact;
        const Vec2 t(c.normal.y(), -c.normal.x());
        std::vector<Vec2> edges;
        if (c.mu == 0.0) {
            edges = {c.normal};
        } else {
            edges = {c.normal + c.mu * t, c.normal - c.mu * t};
        }
        for (const Vec2& f : edges) {
            const int column = glp_add_cols(p, 1);
            glp_set_col_bnds(p, column, GLP_LO, 0.0, 0.0);
            const double w[3] = {f.x(), f.y(), c.point.x() * f.y() - c.point.y() * f.x()};
            for (int r = 0; r < 3; ++r) {
                if (w[r] == 0.0) continue;
                ia.push_back(static_cast<int>(3 * (ac.a - 1)) + r + 1);
                ja.push_back(column);
                ar.push_back(w[r]);
                if (ac.b != 0) {
                    ia.push_back(static_cast<int>(3 * (ac.b - 1)) + r + 1);
                    ja.push_back(column);
                    ar.push_back(-w[r]);
                }
            }
        }
    }
    glp_load_matrix(p, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
    glp_term_out(GLP_OFF);  // glp_scale_prob reports its scaling on the terminal otherwise
    glp_scale_prob(p, GLP_SF_AUTO);
    glp_term_out(GLP_ON);
    return p;
}

std::string case_name(int family, int size) { return std::string(kFamilyNames[family]) + " " + std::to_string(size); }

// Per case: whether it stands, by each solver (1, 0; -1 for a failure).
std::map<std::string, std::map<std::string, int>>& answers() {
    static std::map<std::string, std::map<std::string, int>> a;
    return a;
}

void BM_can_stand(benchmark::State& state) {
    const int family = static_cast<int>(state.range(0)), size = static_cast<int>(state.range(1));
    const Case c = scene(family, size);
    const assembly_detail::LpCounts before = assembly_detail::lp_counts();
    std::size_t runs = 0;
    bool stands = false;
    const Rational2 gravity = rational(c.gravity);
    for (auto _ : state) {
        const Equilibrium e = equilibrium(c.assembly, gravity);
        stands = e.can_stand;
        benchmark::DoNotOptimize(e);
        ++runs;
    }
    const assembly_detail::LpCounts& after = assembly_detail::lp_counts();
    answers()[case_name(family, size)]["ours"] = stands ? 1 : 0;
    state.counters["stands"] = stands;
    state.counters["exact_path"] = static_cast<double>(after.exact - before.exact) / static_cast<double>(runs);
    state.counters["rows"] = static_cast<double>(3 * c.assembly.bodies.size());
}
BENCHMARK(BM_can_stand)->ArgsProduct({{kArch, kThinArch}, {10, 30, 100}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_can_stand)->ArgsProduct({{kWall, kTiltedWall}, {10, 30, 100, 200}})->Unit(benchmark::kMillisecond);

void BM_glpk_build(benchmark::State& state) {
    const Case c = scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    for (auto _ : state) {
        glp_prob* p = glpk_equilibrium(c.assembly, c.gravity);
        benchmark::DoNotOptimize(p);
        glp_delete_prob(p);
    }
}
BENCHMARK(BM_glpk_build)->ArgsProduct({{kArch, kThinArch}, {10, 30, 100}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_glpk_build)->ArgsProduct({{kWall, kTiltedWall}, {10, 30, 100, 200}})->Unit(benchmark::kMillisecond);

template <bool kExact>
void glpk_solve(benchmark::State& state) {
    const int family = static_cast<int>(state.range(0)), size = static_cast<int>(state.range(1));
    const Case c = scene(family, size);
    glp_prob* p = glpk_equilibrium(c.assembly, c.gravity);
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = GLP_MSG_OFF;
    parm.presolve = GLP_OFF;
    int code = 0;
    for (auto _ : state) {
        glp_std_basis(p);
        code = kExact ? glp_exact(p, &parm) : glp_simplex(p, &parm);
        benchmark::DoNotOptimize(code);
    }
    const int status = glp_get_status(p);
    const int stands = code != 0 ? -1 : status == GLP_OPT || status == GLP_FEAS ? 1 : status == GLP_NOFEAS ? 0 : -1;
    answers()[case_name(family, size)][kExact ? "glp_exact" : "glp_simplex"] = stands;
    state.counters["stands"] = stands;
    glp_delete_prob(p);
}
void BM_glp_simplex(benchmark::State& state) { glpk_solve<false>(state); }
void BM_glp_exact(benchmark::State& state) { glpk_solve<true>(state); }
BENCHMARK(BM_glp_simplex)->ArgsProduct({{kArch, kThinArch}, {10, 30, 100}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_glp_simplex)->ArgsProduct({{kWall, kTiltedWall}, {10, 30, 100, 200}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_glp_exact)->ArgsProduct({{kArch, kThinArch}, {10, 30, 100}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_glp_exact)->ArgsProduct({{kWall, kTiltedWall}, {10, 30, 100, 200}})->Unit(benchmark::kMillisecond);

// The mode enumeration on assemblies of 2-4 bodies (bodies, contacts in the name).
struct ModesCase {
    const char* name;
    Assembly assembly;
};

std::vector<ModesCase> modes_cases() {
    return {
        {"tower of 2 bricks, offset 1/2", tower(2, 2, 0.5, 0.5)},
        {"tower of 3 bricks, offset 1/2", tower(3, 2, 0.5, 0.5)},
        {"tower of 4 bricks, offset 1/2", tower(4, 2, 0.5, 0.5)},
        {"tower of 4 bricks, 3 points a face", tower(4, 3, 0.5, 0.5)},
        {"wall of 3 bricks, 2 a row, running bond", running_bond_wall(3, 2, 0.5)},
        {"wall of 4 bricks, 1 a row, running bond", running_bond_wall(4, 1, 0.5)},
        {"arch of 2 voussoirs", dyadic_arch(2, 1, 0.5)},
        {"arch of 3 voussoirs", dyadic_arch(3, 1, 0.5)},
        {"arch of 4 voussoirs", dyadic_arch(4, 1, 0.5)},
        {"arch of 3 voussoirs, 3 points a joint", dyadic_arch(3, 1, 0.5, 3)},
    };
}

void BM_modes(benchmark::State& state) {
    const ModesCase c = modes_cases()[static_cast<std::size_t>(state.range(0))];
    std::size_t modes = 0, motions = 0;
    for (auto _ : state) {
        const AssemblyModes m = assembly_modes(c.assembly, kDefaultGravity);
        modes = m.modes.size();
        motions = m.motions.size();
        benchmark::DoNotOptimize(m);
    }
    state.SetLabel(c.name);
    state.counters["bodies"] = static_cast<double>(c.assembly.bodies.size());
    state.counters["contacts"] = static_cast<double>(c.assembly.contacts.size());
    state.counters["modes"] = static_cast<double>(modes);
    state.counters["motions"] = static_cast<double>(motions);
}
BENCHMARK(BM_modes)->DenseRange(0, 9)->Unit(benchmark::kMillisecond);

class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;
    std::map<std::string, std::map<std::string, double>> counters;
    std::map<std::string, std::string> labels;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            const std::string name = r.benchmark_name();
            seconds[name] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
            for (const auto& [k, v] : r.counters) counters[name][k] = v.value;
            labels[name] = r.report_label;
        }
    }
    void print() const {
        std::printf("\ncan_stand beside GLPK on the same program (ms per decision; ratios: ours / GLPK's solve)\n");
        std::printf("%-24s %6s %6s %8s %10s %10s %10s %10s %9s %9s %6s %s\n", "scene", "rows", "cols", "exact", "ours",
                    "glp_simp", "glp_exact", "glp_build", "/simplex", "/exact", "stands", "(ours/simplex/exact)");
        const std::vector<std::pair<int, std::vector<int>>> cases = {{kArch, {10, 30, 100}},
                                                                     {kThinArch, {10, 30, 100}},
                                                                     {kWall, {10, 30, 100, 200}},
                                                                     {kTiltedWall, {10, 30, 100, 200}}};
        for (const auto& [family, sizes] : cases) {
            for (int size : sizes) {
                std::string args = "/";
                args += std::to_string(family);
                args += "/";
                args += std::to_string(size);
                const auto ours = seconds.find("BM_can_stand" + args);
                const auto simplex = seconds.find("BM_glp_simplex" + args);
                const auto exact = seconds.find("BM_glp_exact" + args);
                const auto build = seconds.find("BM_glpk_build" + args);
                if (ours == seconds.end() || simplex == seconds.end() || exact == seconds.end() || build == seconds.end()) continue;
                const Case c = scene(family, size);
                std::size_t columns = 0;
                for (const AssemblyContact& ac : c.assembly.contacts) columns += ac.contact.mu == 0.0 ? 1 : 2;
                const auto& a = answers().at(case_name(family, size));
                std::printf("%-24s %6zu %6zu %8.2f %10.3f %10.3f %10.3f %10.3f %9.2f %9.2f %6s %d/%d/%d\n",
                            case_name(family, size).c_str(), 3 * c.assembly.bodies.size(), columns,
                            counters.at("BM_can_stand" + args).at("exact_path"), 1e3 * ours->second, 1e3 * simplex->second,
                            1e3 * exact->second, 1e3 * build->second, ours->second / simplex->second,
                            ours->second / exact->second, a.at("ours") ? "yes" : "no", a.at("ours"), a.at("glp_simplex"),
                            a.at("glp_exact"));
            }
        }
        std::printf("\nassembly_modes (ms per enumeration)\n");
        std::printf("%-40s %7s %9s %6s %8s %10s\n", "scene", "bodies", "contacts", "modes", "motions", "ms");
        for (int k = 0; k < 10; ++k) {
            const std::string name = "BM_modes/" + std::to_string(k);
            const auto s = seconds.find(name);
            if (s == seconds.end()) continue;
            const auto& c = counters.at(name);
            std::printf("%-40s %7.0f %9.0f %6.0f %8.0f %10.2f\n", labels.at(name).c_str(), c.at("bodies"), c.at("contacts"),
                        c.at("modes"), c.at("motions"), 1e3 * s->second);
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    reporter.print();
    benchmark::Shutdown();
    return 0;
}
