// bench_cone: the cone of n generators, n = 4 .. 10^6, three families, beside cddlib
// (floating point and GMP, where they finish within about a minute) and a plain 2-D
// monotone-chain hull of the same n points (the generators seen in the chart z = 1).
// Run `make bench`; the ratios are printed after the Google Benchmark table.
#include <benchmark/benchmark.h>
#include <setoper.h>
#include <cdd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "geometry/cone_build.hpp"
#include "momentlab/geometry/cone.hpp"

namespace {

using momentlab::Cone;
using momentlab::ConeBuilder;
using momentlab::Vec2;
using momentlab::Vec3;

double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

enum Family { kHalfSpace = 0, kCircle = 1, kOnFacets = 2 };
const char* kFamilyNames[] = {"random in a half-space", "all extreme (circle)", "on the facets of a pyramid"};

// Generators with z > 0 so that the 2-D hull of (x/z, y/z) is the same problem.
std::vector<Vec3> make(Family f, std::int64_t n) {
    std::mt19937_64 rng(42 + static_cast<std::uint64_t>(n) + 1000u * f);
    std::vector<Vec3> g;
    g.reserve(static_cast<std::size_t>(n));
    const double kTwoPi = 6.283185307179586;
    for (std::int64_t i = 0; i < n; ++i) {
        if (f == kHalfSpace) {
            g.emplace_back(2 * unit(rng) - 1, 2 * unit(rng) - 1, 0.05 + unit(rng));
        } else if (f == kCircle) {
            const double t = kTwoPi * (static_cast<double>(i) + 0.5 * unit(rng)) / static_cast<double>(n);
            g.emplace_back(std::cos(t), std::sin(t), 1.0);
        } else {
            // Integer points on the four side faces of the pyramid |x|, |y| <= m z (exactly
            // on a facet), every fifth one strictly inside, and the 4 corners: 4 facets, 4 rays.
            const std::int64_t m = std::max<std::int64_t>(2, n / 5);
            if (i < 4) {  // the four corners
                g.emplace_back(i % 2 ? m : -m, i / 2 ? m : -m, m);
                continue;
            }
            const double k = static_cast<double>(static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m);
            const double md = static_cast<double>(m);
            switch (i % 5) {
                case 0: g.emplace_back(k, md, 1.0 * md); break;
                case 1: g.emplace_back(k, -md, md); break;
                case 2: g.emplace_back(md, k, md); break;
                case 3: g.emplace_back(-md, k, md); break;
                default: g.emplace_back(std::trunc(k / 2), std::trunc(k / 3), md); break;
            }
        }
    }
    return g;
}

std::int64_t expected_facets(Family f, std::int64_t n) { return f == kCircle ? n : (f == kOnFacets ? 4 : -1); }

// Andrew's monotone chain on doubles: the speed baseline (not robust).
std::size_t monotone_chain(std::vector<Vec2> p) {
    std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    std::vector<Vec2> h(2 * p.size());
    std::size_t k = 0;
    auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    return k - 1;
}

void BM_momentlab(benchmark::State& state) {
    const auto f = static_cast<Family>(state.range(0));
    const auto g = make(f, state.range(1));
    std::size_t facets = 0;
    for (auto _ : state) {
        const Cone c = Cone::from_generators(g);
        facets = c.facets().size();
        benchmark::DoNotOptimize(facets);
    }
    state.counters["facets"] = static_cast<double>(facets);
    state.counters["expected"] = static_cast<double>(expected_facets(f, state.range(1)));
}

// The same cones with the chart path switched off (ConeBuilder::use_chart): the pivot path that
// built every cone before it, for the small sizes the chart takes (up to 128 generators).
void BM_momentlab_pivot(benchmark::State& state) {
    ConeBuilder::use_chart() = false;
    BM_momentlab(state);
    ConeBuilder::use_chart() = true;
}

void BM_hull2d(benchmark::State& state) {
    const auto f = static_cast<Family>(state.range(0));
    const auto g = make(f, state.range(1));
    std::vector<Vec2> pts;
    for (const Vec3& v : g) pts.emplace_back(v.x() / v.z(), v.y() / v.z());
    std::size_t facets = 0;
    for (auto _ : state) {
        facets = monotone_chain(pts);
        benchmark::DoNotOptimize(facets);
    }
    state.counters["facets"] = static_cast<double>(facets);
}

// cddlib: V-representation (origin + rays) to H-representation.
template <bool kExact>
void BM_cdd(benchmark::State& state) {
    static bool init = (dd_set_global_constants(), true);
    (void)init;
    const auto f = static_cast<Family>(state.range(0));
    const auto g = make(f, state.range(1));
    const long rows = static_cast<long>(g.size()) + 1;
    long facets = 0;
    for (auto _ : state) {
        if constexpr (kExact) {
            dd_MatrixPtr m = dd_CreateMatrix(rows, 4);
            m->representation = dd_Generator;
            m->numbtype = dd_Rational;
            dd_set_si(m->matrix[0][0], 1);
            for (long r = 1; r < rows; ++r) {
                dd_set_si(m->matrix[r][0], 0);
                for (int j = 0; j < 3; ++j) mpq_set_d(m->matrix[r][j + 1], g[static_cast<std::size_t>(r - 1)][j]);
            }
            dd_ErrorType err;
            dd_PolyhedraPtr p = dd_DDMatrix2Poly(m, &err);
            dd_MatrixPtr h = dd_CopyInequalities(p);
            facets = h->rowsize - 1;  // less the trivial row 1 >= 0
            dd_FreeMatrix(h);
            dd_FreePolyhedra(p);
            dd_FreeMatrix(m);
        } else {
            ddf_MatrixPtr m = ddf_CreateMatrix(rows, 4);
            m->representation = ddf_Generator;
            m->numbtype = ddf_Real;
            ddf_set_si(m->matrix[0][0], 1);
            for (long r = 1; r < rows; ++r) {
                ddf_set_si(m->matrix[r][0], 0);
                for (int j = 0; j < 3; ++j) ddf_set_d(m->matrix[r][j + 1], g[static_cast<std::size_t>(r - 1)][j]);
            }
            ddf_ErrorType err;
            ddf_PolyhedraPtr p = ddf_DDMatrix2Poly(m, &err);
            ddf_MatrixPtr h = ddf_CopyInequalities(p);
            facets = h->rowsize - 1;
            ddf_FreeMatrix(h);
            ddf_FreePolyhedra(p);
            ddf_FreeMatrix(m);
        }
        benchmark::DoNotOptimize(facets);
    }
    state.counters["facets"] = static_cast<double>(facets);
}

void sizes(benchmark::internal::Benchmark* b, std::int64_t max_n) {
    for (int f = 0; f < 3; ++f) {
        for (std::int64_t n : {4, 10, 30}) b->Args({f, n});  // small cones: the fixed cost
        for (std::int64_t n = 100; n <= max_n; n *= 10) b->Args({f, n});
    }
    b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_momentlab)->Apply([](auto* b) { sizes(b, 1000000); });
BENCHMARK(BM_momentlab_pivot)->Apply([](auto* b) { sizes(b, 100); });
BENCHMARK(BM_hull2d)->Apply([](auto* b) { sizes(b, 1000000); });
BENCHMARK(BM_cdd<false>)->Name("BM_cdd_float")->Apply([](auto* b) { sizes(b, 10000); })->Iterations(1);
BENCHMARK(BM_cdd<true>)->Name("BM_cdd_gmp")->Apply([](auto* b) { sizes(b, 1000); })->Iterations(1);

// Collects the runs so that the ratios can be printed after the usual table.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    struct Row {
        double ms = 0;
        double facets = -1;
    };
    std::map<std::string, std::map<std::pair<int, std::int64_t>, Row>> rows;

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            const std::string name = r.benchmark_name();
            const auto slash = name.find('/');
            int f = 0;
            long long n = 0;
            std::sscanf(name.c_str() + slash, "/%d/%lld", &f, &n);
            Row row;
            row.ms = r.GetAdjustedRealTime();
            const auto it = r.counters.find("facets");
            if (it != r.counters.end()) row.facets = it->second;
            rows[name.substr(0, slash)][{f, n}] = row;
        }
    }

    void print_ratios() const {
        std::printf("\nRatios (time / time of the plain 2-D monotone-chain hull of the same points);"
                    " facets found vs expected\n");
        std::printf("%-28s %8s %11s %11s %9s %11s %9s %11s %9s %11s %9s  %s\n", "family", "n", "hull2d ms",
                    "momentlab", "ratio", "pivot path", "ratio", "cdd float", "ratio", "cdd gmp", "ratio",
                    "facets: ours / cdd float / expected");
        const auto& ours = rows.at("BM_momentlab");
        for (const auto& [key, row] : ours) {
            const double hull = rows.at("BM_hull2d").at(key).ms;
            auto get = [&](const char* name) -> const Row* {
                const auto it = rows.find(name);
                if (it == rows.end()) return nullptr;
                const auto jt = it->second.find(key);
                return jt == it->second.end() ? nullptr : &jt->second;
            };
            const Row* cf = get("BM_cdd_float");
            const Row* cg = get("BM_cdd_gmp");
            const Row* pv = get("BM_momentlab_pivot");
            char cf_ms[32] = "-", cf_r[32] = "-", cg_ms[32] = "-", cg_r[32] = "-", cf_n[32] = "-", pv_ms[32] = "-", pv_r[32] = "-";
            if (pv) {
                std::snprintf(pv_ms, sizeof pv_ms, "%.4g", pv->ms);
                std::snprintf(pv_r, sizeof pv_r, "%.1f", pv->ms / hull);
            }
            if (cf) {
                std::snprintf(cf_ms, sizeof cf_ms, "%.4g", cf->ms);
                std::snprintf(cf_r, sizeof cf_r, "%.1f", cf->ms / hull);
                std::snprintf(cf_n, sizeof cf_n, "%.0f", cf->facets);
            }
            if (cg) {
                std::snprintf(cg_ms, sizeof cg_ms, "%.4g", cg->ms);
                std::snprintf(cg_r, sizeof cg_r, "%.1f", cg->ms / hull);
            }
            // Known counts for the constructed families; for random generators the 2-D hull's
            // count (the same problem in the chart z = 1).
            auto expected = expected_facets(static_cast<Family>(key.first), key.second);
            if (expected < 0) expected = static_cast<std::int64_t>(rows.at("BM_hull2d").at(key).facets);
            std::printf("%-28s %8lld %11.4g %11.4g %9.2f %11s %9s %11s %9s %11s %9s  %.0f / %s / %s\n",
                        kFamilyNames[key.first], static_cast<long long>(key.second), hull, row.ms,
                        row.ms / hull, pv_ms, pv_r, cf_ms, cf_r, cg_ms, cg_r, row.facets, cf_n,
                        std::to_string(expected).c_str());
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    if (reporter.rows.count("BM_momentlab") && reporter.rows.count("BM_hull2d")) reporter.print_ratios();
    benchmark::Shutdown();
    return 0;
}
