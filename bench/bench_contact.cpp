// bench_contact: contact modes and every applied-wrench set E_i for n = 10 .. 10^5 contacts,
// and `query` throughput on scenes of 2 .. 8 contacts beside one solve of the same question
// as the standard acceleration-level planar Coulomb LCP with Siconos Numerics' Lemke solver
// (two friction directions per contact; docs/benchmarks.md). `make bench` prints the ratios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <vector>

#include "coulomb_lcp.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "momentlab/mechanics/find_contacts.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/query_index.hpp"

namespace {

using namespace momentlab;

double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// A polygonal body resting in a cradle: n contacts on the lower half of a regular polygon,
// normals pointing to its centre.
Scene cradle(std::int64_t n) {
    Scene s;
    s.body = Body{1.0, Vec2(0, 0), 0.5, {}};
    for (std::int64_t k = 0; k < n; ++k) {
        const double a = M_PI * (1.0 + (static_cast<double>(k) + 0.5) / static_cast<double>(n));
        const Vec2 p(std::cos(a), std::sin(a));
        s.contacts.push_back(Contact::make(p, -p, 0.3));
    }
    return s;
}

// n contacts on a flat floor under a long box.
Scene floor_contacts(std::int64_t n) {
    Scene s;
    s.body = Body{1.0, Vec2(0.5 * static_cast<double>(n), 0.5), 1.0, {}};
    for (std::int64_t k = 0; k < n; ++k) s.contacts.push_back(Contact::make(Vec2(static_cast<double>(k), 0), Vec2(0, 1), 0.3));
    return s;
}

void BM_modes_and_sets(benchmark::State& state) {
    const Scene s = state.range(0) == 0 ? cradle(state.range(1)) : floor_contacts(state.range(1));
    std::size_t modes = 0;
    for (auto _ : state) {
        const auto a = analyze(s);
        modes = a.size();
        benchmark::DoNotOptimize(modes);
    }
    state.counters["modes"] = static_cast<double>(modes);
}
BENCHMARK(BM_modes_and_sets)->ArgsProduct({{0, 1}, {10, 100, 1000, 10000, 100000}})->Unit(benchmark::kMillisecond);

// Random scenes with n contacts under a box (on the lower half of an ellipse around it, normals
// roughly towards its centre), and random applied wrenches.
Scene random_scene(int n, std::mt19937_64& rng) {
    Scene s;
    s.body = Body{1.0, Vec2(0.5, 0.25), 0.1, {}};
    for (int j = 0; j < n; ++j) {
        const double a = M_PI * (1.0 + unit(rng));  // supports below: the body can move
        const Vec2 p(0.5 + 0.6 * std::cos(a), 0.25 + 0.4 * std::sin(a));
        const Vec2 nrm = Vec2(0.5, 0.25) - p + Vec2(0.3 * unit(rng) - 0.15, 0.3 * unit(rng) - 0.15);
        s.contacts.push_back(Contact::make(p, nrm, 0.1 + unit(rng)));
    }
    return s;
}

std::vector<Vec3> random_wrenches(std::mt19937_64& rng) {
    std::vector<Vec3> w;
    for (int i = 0; i < 1024; ++i) w.emplace_back(20 * unit(rng) - 10, 20 * unit(rng) - 10, 20 * unit(rng) - 10);
    return w;
}

void BM_query(benchmark::State& state) {
    std::mt19937_64 rng(7 + static_cast<std::uint64_t>(state.range(0)));
    const Scene s = random_scene(static_cast<int>(state.range(0)), rng);
    const auto a = analyze(s);
    const QueryIndex index(a);
    const auto w = random_wrenches(rng);
    std::vector<std::size_t> modes;
    std::size_t i = 0, found = 0;
    for (auto _ : state) {
        index.query(w[i++ & 1023], modes);
        found += modes.size();
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
    state.counters["modes"] = static_cast<double>(a.size());
    state.counters["planes"] = static_cast<double>(index.planes());
}
BENCHMARK(BM_query)->DenseRange(2, 8, 2);

// The same questions by testing each E_i in turn (query(analysis, e)), for comparison.
void BM_query_per_mode(benchmark::State& state) {
    std::mt19937_64 rng(7 + static_cast<std::uint64_t>(state.range(0)));
    const Scene s = random_scene(static_cast<int>(state.range(0)), rng);
    const auto a = analyze(s);
    const auto w = random_wrenches(rng);
    std::size_t i = 0, found = 0;
    for (auto _ : state) found += query(a, w[i++ & 1023]).modes.size();
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_query_per_mode)->DenseRange(2, 8, 2);

// The same question as the standard acceleration-level planar Coulomb LCP (4n unknowns; written
// out in docs/validation.md), solved by Siconos' lexicographic Lemke (validation/coulomb_lcp.hpp).
void BM_lemke(benchmark::State& state) {
    std::mt19937_64 rng(7 + static_cast<std::uint64_t>(state.range(0)));
    const Scene s = random_scene(static_cast<int>(state.range(0)), rng);
    const auto w = random_wrenches(rng);
    validation::CoulombLcp lcp(s);
    validation::LcpSolution solution;
    std::size_t i = 0;
    int failures = 0;
    for (auto _ : state) failures += !lcp.lemke(w[i++ & 1023], solution);
    state.SetItemsProcessed(state.iterations());
    state.counters["failures"] = failures;
}
BENCHMARK(BM_lemke)->DenseRange(2, 8, 2);

// A new scene every time (docs/benchmarks.md, "Questions about a scene"): a pool of 512 random scenes with
// one wrench each, taken in turn, so nothing about a scene is cached or reused. momentlab: every
// mode with its sets (analyze), then the modes whose E holds the wrench (query, exact).
constexpr int kPool = 512;

struct Question {
    Scene scene;
    Vec3 wrench;
};

std::vector<Question> fresh_pool(int n) {
    std::mt19937_64 rng(11 + static_cast<std::uint64_t>(n));
    std::vector<Question> pool;
    for (int i = 0; i < kPool; ++i) {
        Scene s = random_scene(n, rng);
        pool.push_back({std::move(s), Vec3(20 * unit(rng) - 10, 20 * unit(rng) - 10, 20 * unit(rng) - 10)});
    }
    return pool;
}

void BM_oneshot(benchmark::State& state) {
    const auto pool = fresh_pool(static_cast<int>(state.range(0)));
    std::size_t i = 0, found = 0;
    for (auto _ : state) {
        const Question& q = pool[i++ % kPool];
        found += query(analyze(q.scene), q.wrench).modes.size();
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_oneshot)->DenseRange(2, 8, 2)->Unit(benchmark::kMicrosecond);

// The same questions by the direct path (query_scene): the modes, then only the sets that no
// certificate of an earlier mode decides.
void BM_oneshot_direct(benchmark::State& state) {
    const auto pool = fresh_pool(static_cast<int>(state.range(0)));
    std::size_t i = 0, found = 0;
    for (auto _ : state) {
        const Question& q = pool[i++ % kPool];
        found += query_scene(q.scene, q.wrench).result.modes.size();
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_oneshot_direct)->DenseRange(2, 8, 2)->Unit(benchmark::kMicrosecond);

// The same questions by query(scene, e), the front door: double arithmetic with certified error
// bounds, the exact path only where a sign is not certified (the counter says how many of the 512
// scenes took it).
void BM_oneshot_once(benchmark::State& state) {
    const auto pool = fresh_pool(static_cast<int>(state.range(0)));
    std::size_t i = 0, found = 0;
    int exact = 0;
    for (auto _ : state) {
        const Question& q = pool[i % kPool];
        QueryDiagnostics how;
        const QueryAnswer a = query(q.scene, q.wrench, {}, how);
        found += a.letters.size();
        if (i++ < kPool) exact += !how.filtered;
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
    state.counters["exact_path"] = exact;
}
BENCHMARK(BM_oneshot_once)->DenseRange(2, 8, 2)->Unit(benchmark::kMicrosecond);

// The same kind of questions on scenes whose numbers have three decimals (docs/design.md,
// "Numbers as typed"): read as binary doubles (arg 0, Contact::make of doubles) and as the
// decimals they spell (arg 1, Contact::make of Rationals, as a scene file reads them), side by
// side; the wrench is the same double. The ratio of the two is the cost of reading decimals.
std::vector<Question> decimal_pool(int n, bool decimal) {
    std::mt19937_64 rng(46 + static_cast<std::uint64_t>(n));
    const auto three_places = [&](double lo, double hi) {
        const auto k = static_cast<std::int64_t>(std::llround((lo + (hi - lo) * unit(rng)) * 1000.0));
        return Rational(Dyadic::from_integer(k), Dyadic::from_integer(1000));
    };
    std::vector<Question> pool;
    for (int i = 0; i < kPool; ++i) {
        Scene s;
        s.body = Body{1.0, Vec2(0.5, 0.25), 0.1, {}};
        for (int j = 0; j < n; ++j) {
            const double a = M_PI * (1.0 + unit(rng));
            const Rational2 p{three_places(0.5 + 0.6 * std::cos(a), 0.5 + 0.6 * std::cos(a)),
                              three_places(0.25 + 0.4 * std::sin(a), 0.25 + 0.4 * std::sin(a))};
            const Rational2 nrm{Rational(0.5) - p[0] + three_places(-0.15, 0.15), Rational(0.25) - p[1] + three_places(-0.15, 0.15)};
            const Rational mu = three_places(0.1, 1.1);
            s.contacts.push_back(decimal ? Contact::make(p, nrm, mu) : Contact::make(to_double(p), to_double(nrm), mu.to_double()));
        }
        pool.push_back({std::move(s), Vec3(20 * unit(rng) - 10, 20 * unit(rng) - 10, 20 * unit(rng) - 10)});
    }
    return pool;
}

void BM_oneshot_decimals(benchmark::State& state) {
    const auto pool = decimal_pool(static_cast<int>(state.range(0)), state.range(1) != 0);
    std::size_t i = 0, found = 0;
    int exact = 0;
    for (auto _ : state) {
        const Question& q = pool[i % kPool];
        QueryDiagnostics how;
        found += query(q.scene, q.wrench, {}, how).letters.size();
        if (i++ < kPool) exact += !how.filtered;
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
    state.counters["exact_path"] = exact;
}
BENCHMARK(BM_oneshot_decimals)->ArgsProduct({{2, 4, 8}, {0, 1}})->Unit(benchmark::kMicrosecond);

// The same scenes analysed (every mode's sets, exact), binary and decimal.
void BM_analyze_decimals(benchmark::State& state) {
    const auto pool = decimal_pool(static_cast<int>(state.range(0)), state.range(1) != 0);
    std::size_t i = 0, found = 0;
    for (auto _ : state) found += analyze(pool[i++ % kPool].scene).size();
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_analyze_decimals)->ArgsProduct({{4, 8}, {0, 1}})->Unit(benchmark::kMicrosecond);

// The same questions as a simulator asks them: the LCP of the new scene assembled into reused
// buffers (CoulombLcp::reset), then solved by Siconos' lexicographic Lemke.
void BM_lemke_oneshot(benchmark::State& state) {
    const auto pool = fresh_pool(static_cast<int>(state.range(0)));
    validation::CoulombLcp lcp(pool.front().scene);
    validation::LcpSolution solution;
    std::size_t i = 0;
    int failures = 0;
    for (auto _ : state) {
        const Question& q = pool[i++ % kPool];
        lcp.reset(q.scene);
        failures += !lcp.lemke(q.wrench, solution);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["failures"] = failures;
}
BENCHMARK(BM_lemke_oneshot)->DenseRange(2, 8, 2)->Unit(benchmark::kMicrosecond);

// The nearly degenerate families of docs/benchmarks.md (tools/families.py writes the same scenes
// for the command line): a unit body, mu = 0.3, n contacts.
Scene family(int which, std::int64_t n) {
    Scene s;
    s.body = Body{1.0, Vec2(0, 0), 0.5, {}};
    const auto round9 = [](double x) { return std::round(x * 1e9) / 1e9; };
    for (std::int64_t k = 0; k < n; ++k) {
        const double a = M_PI * (1.0 + (static_cast<double>(k) + 0.5) / static_cast<double>(n));
        const double c = std::cos(a), si = std::sin(a);
        switch (which) {
            case 0:  // bowl: normals towards the centre, rounded to 9 digits (nearly concurrent)
                s.contacts.push_back(Contact::make(Vec2(round9(c), round9(si)), Vec2(round9(-c), round9(-si)), 0.3));
                break;
            case 1:  // bowl, exactly concurrent: normal -p
                s.contacts.push_back(Contact::make(Vec2(round9(c), round9(si)), Vec2(-round9(c), -round9(si)), 0.3));
                break;
            case 2: {  // every normal on the x axis
                const double x = (static_cast<double>(k) + 0.5) / static_cast<double>(n) * 4.0 - 2.0;
                s.contacts.push_back(Contact::make(Vec2(x, 0), Vec2(k % 2 == 0 ? 1.0 : -1.0, 0), 0.3));
                break;
            }
            case 3: {  // a half ring, normals tilted by 0.2 rad from the radius (a cradle)
                const double t = 0.2;
                s.contacts.push_back(Contact::make(Vec2(c, si), Vec2(-(c * std::cos(t) - si * std::sin(t)), -(c * std::sin(t) + si * std::cos(t))), 0.3));
                break;
            }
            default:  // normal lines tangent to the half circle
                s.contacts.push_back(Contact::make(Vec2(c, si), Vec2(-si, c), 0.3));
        }
    }
    return s;
}

const char* const kFamilies[] = {"bowl", "bowl-exact", "collinear", "cradle", "tangent"};

void BM_family_modes(benchmark::State& state) {
    const Scene s = family(static_cast<int>(state.range(0)), state.range(1));
    std::size_t modes = 0;
    for (auto _ : state) modes = enumerate_modes(s.contacts).modes.size();
    state.SetLabel(kFamilies[state.range(0)]);
    state.counters["modes"] = static_cast<double>(modes);
    state.counters["letters"] = static_cast<double>(modes) * static_cast<double>(state.range(1));
}
BENCHMARK(BM_family_modes)->ArgsProduct({{0, 1}, {100000}})->ArgsProduct({{2, 3, 4}, {1000, 3000}})->Unit(benchmark::kMillisecond);

void BM_family_analyze(benchmark::State& state) {
    const Scene s = family(static_cast<int>(state.range(0)), state.range(1));
    std::size_t modes = 0;
    for (auto _ : state) modes = analyze(s).size();
    state.SetLabel(kFamilies[state.range(0)]);
    state.counters["modes"] = static_cast<double>(modes);
}
BENCHMARK(BM_family_analyze)->ArgsProduct({{0, 1}, {100000}})->ArgsProduct({{2, 3, 4}, {1000}})->Unit(benchmark::kMillisecond);

// One wrench (0.1, 1, 0.2) asked of a family scene by the direct path, against query(analyze())
// in the same run; `built` counts the modes whose E the certificates could not decide.
void BM_family_query(benchmark::State& state) {
    const Scene s = family(static_cast<int>(state.range(0)), state.range(1));
    const Vec3 e(0.1, 1.0, 0.2);
    SceneAnswer a;
    QueryDiagnostics work;
    for (auto _ : state) a = query_scene(s, e, {}, &work);
    state.SetLabel(kFamilies[state.range(0)]);
    state.counters["modes"] = static_cast<double>(a.mode_count);
    state.counters["built"] = static_cast<double>(work.built);
}
BENCHMARK(BM_family_query)
    ->ArgsProduct({{0, 1}, {100000}})
    ->ArgsProduct({{2, 3, 4}, {1000}})
    ->ArgsProduct({{3, 4}, {100000}})  // a query needs no mode's letters: the cradle and tangent at 10^5 too
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_family_query_analyzed(benchmark::State& state) {
    const Scene s = family(static_cast<int>(state.range(0)), state.range(1));
    const Vec3 e(0.1, 1.0, 0.2);
    for (auto _ : state) benchmark::DoNotOptimize(query(analyze(s), e));
    state.SetLabel(kFamilies[state.range(0)]);
}
BENCHMARK(BM_family_query_analyzed)->ArgsProduct({{0, 1}, {100000}})->ArgsProduct({{2, 3, 4}, {1000}})->Unit(benchmark::kMillisecond);

// A wavy closed outline of n vertices (radius 1 + sin(7 t) / 10) and a floor of n vertices whose
// top edge runs along the outline's lowest point: the simplicity check of both and the contact
// search between them, as a scene with a detailed body on a detailed terrain asks.
Polygon wavy(std::int64_t n) {
    Polygon p;
    for (std::int64_t i = 0; i < n; ++i) {
        const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n), r = 1.0 + 0.1 * std::sin(7.0 * t);
        p.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    return p;
}

Polygon terrain(std::int64_t n, double top) {
    Polygon p;
    for (std::int64_t i = 0; i < n; ++i) p.emplace_back(-2.0 + 4.0 * static_cast<double>(i) / static_cast<double>(n), top);
    p.emplace_back(2.0, top - 2.0);
    p.emplace_back(-2.0, top - 2.0);
    return p;
}

// The wavy body of n vertices and the terrain of n vertices along its lowest point.
std::pair<Polygon, Polygon> body_on_terrain(std::int64_t n) {
    Polygon body = wavy(n);
    double low = 0.0;
    for (const Vec2& v : body) low = std::min(low, v.y());
    return {std::move(body), terrain(n, low)};
}

void BM_polygon_simple(benchmark::State& state) {
    const Polygon p = wavy(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(polygon_problem(p));
    state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_polygon_simple)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->Complexity();

void BM_find_contacts(benchmark::State& state) {
    const auto [body, floor] = body_on_terrain(state.range(0));
    const std::vector<Polygon> obstacles = {floor};
    std::size_t found = 0;
    for (auto _ : state) found = find_contacts(body, obstacles).size();
    state.counters["contacts"] = static_cast<double>(found);
    state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_find_contacts)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->Complexity();

// The same without the exact overlap check (polygons_overlap) that find_contacts runs after the
// simplicity checks.
void BM_find_contacts_without_overlap_check(benchmark::State& state) {
    const auto [body, floor] = body_on_terrain(state.range(0));
    const std::vector<Polygon> obstacles = {floor};
    for (auto _ : state) {
        benchmark::DoNotOptimize(polygon_problem(body).size() + polygon_problem(floor).size());
        benchmark::DoNotOptimize(detail::find_contacts_of_simple(body, obstacles, {}).size());
    }
}
BENCHMARK(BM_find_contacts_without_overlap_check)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

// The alternative: every vertex against every edge (what find_contacts did before its grid).
void BM_find_contacts_all_pairs(benchmark::State& state) {
    const auto [body, floor] = body_on_terrain(state.range(0));
    std::size_t found = 0;
    for (auto _ : state) {
        found = 0;
        for (const Vec2& v : body) {
            for (std::size_t k = 0; k < floor.size(); ++k) found += within_distance_of_segment(v, floor[k], floor[(k + 1) % floor.size()], 1e-9);
        }
        for (const Vec2& v : floor) {
            for (std::size_t k = 0; k < body.size(); ++k) found += within_distance_of_segment(v, body[k], body[(k + 1) % body.size()], 1e-9);
        }
        benchmark::DoNotOptimize(found);
    }
}
BENCHMARK(BM_find_contacts_all_pairs)->RangeMultiplier(10)->Range(1000, 10000)->Unit(benchmark::kMillisecond);

class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;  // name -> seconds per iteration
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            seconds[r.benchmark_name()] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
        }
    }
    void print() const {
        std::printf("\nQueries per second and the ratio to one Siconos Lemke solve of the same LCP\n");
        std::printf("%10s %16s %16s %10s\n", "contacts", "query /s", "lemke /s", "ratio");
        for (int n = 2; n <= 8; n += 2) {
            const auto q = seconds.find("BM_query/" + std::to_string(n));
            const auto l = seconds.find("BM_lemke/" + std::to_string(n));
            if (q == seconds.end() || l == seconds.end()) continue;
            std::printf("%10d %16.0f %16.0f %10.1f\n", n, 1.0 / q->second, 1.0 / l->second, l->second / q->second);
        }
        std::printf("\nA new scene: every mode and its sets plus one query (analyze), the direct path\n"
                    "(query_scene), one question in certified doubles (query), the LCP assembled\n"
                    "and solved by Siconos' Lemke; microseconds per question over 512 scenes, and\n"
                    "each momentlab time over Lemke's\n");
        std::printf("%10s %10s %10s %10s %10s %9s %9s %9s\n", "contacts", "analyze", "direct", "once", "lemke", "ratio",
                    "direct", "once");
        for (int n = 2; n <= 8; n += 2) {
            const auto o = seconds.find("BM_oneshot/" + std::to_string(n));
            const auto d = seconds.find("BM_oneshot_direct/" + std::to_string(n));
            const auto f = seconds.find("BM_oneshot_once/" + std::to_string(n));
            const auto l = seconds.find("BM_lemke_oneshot/" + std::to_string(n));
            if (o == seconds.end() || d == seconds.end() || f == seconds.end() || l == seconds.end()) continue;
            std::printf("%10d %10.2f %10.2f %10.2f %10.2f %9.2f %9.2f %9.2f\n", n, 1e6 * o->second, 1e6 * d->second,
                        1e6 * f->second, 1e6 * l->second, o->second / l->second, d->second / l->second, f->second / l->second);
        }
        std::printf("\nPolygons of n vertices: simplicity, contact search (grid), and every pair (the alternative)\n");
        std::printf("%10s %14s %14s %14s %10s\n", "n", "simple (ms)", "contacts (ms)", "all pairs (ms)", "ratio");
        for (int n = 1000; n <= 1000000; n *= 10) {
            const auto s1 = seconds.find("BM_polygon_simple/" + std::to_string(n));
            const auto c = seconds.find("BM_find_contacts/" + std::to_string(n));
            const auto b = seconds.find("BM_find_contacts_all_pairs/" + std::to_string(n));
            if (s1 == seconds.end() || c == seconds.end()) continue;
            std::printf("%10d %14.2f %14.2f", n, 1e3 * s1->second, 1e3 * c->second);
            if (b != seconds.end()) {
                std::printf(" %14.2f %10.1f\n", 1e3 * b->second, b->second / c->second);
            } else {
                std::printf(" %14s %10s\n", "-", "-");
            }
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
