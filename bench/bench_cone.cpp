// bench_cone: the cone of n generators, n = 4 .. 10^6, three families, beside cddlib
// (floating point and GMP, where they finish within about a minute), a plain 2-D
// monotone-chain hull of the same n points (the generators seen in the chart z = 1) and, for
// small cones, a plain hull of the cone in doubles (plain_cone_hull).
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

// A plain (non-robust) hull of the cone: the job Cone::from_generators does for a pointed cone,
// in doubles, written as a user would write it. The chart: the mean of the generators' directions
// (moved towards any generator behind it, as the library's chart is), then Andrew's monotone chain
// on the points (f . g, e . g) / (d . g), and the cone's two lists: its extreme rays and the facet
// normals r_i x r_i+1. The speed baseline for small cones beside the 2-D chain above, which is
// given its points already in the chart z = 1 and returns a count.
struct PlainCone {
    std::vector<Vec3> rays, facets;
};
struct ChartPoint {
    double x, y;
    int index;
};
PlainCone plain_cone_hull(const std::vector<Vec3>& g) {
    Vec3 d = Vec3::Zero();
    for (const Vec3& v : g) d += v / v.cwiseAbs().sum();
    for (int pass = 0; pass < 8; ++pass) {
        bool moved = false;
        for (const Vec3& v : g) {
            if (!(d.dot(v) > 0)) {
                d += v / v.cwiseAbs().sum();
                moved = true;
            }
        }
        if (!moved) break;
    }
    int k = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::fabs(d[i]) < std::fabs(d[k])) k = i;
    }
    const Vec3 e = Vec3::Unit(k).cross(d), f = e.cross(d);
    std::vector<ChartPoint> p;
    p.reserve(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double w = d.dot(g[i]);
        p.push_back({f.dot(g[i]) / w, e.dot(g[i]) / w, static_cast<int>(i)});
    }
    std::sort(p.begin(), p.end(), [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<int> h(2 * p.size());
    std::size_t m = 0;
    auto turn = [&](int o, int a, int b) {
        const ChartPoint &po = p[static_cast<std::size_t>(o)], &pa = p[static_cast<std::size_t>(a)], &pb = p[static_cast<std::size_t>(b)];
        return (pa.x - po.x) * (pb.y - po.y) - (pa.y - po.y) * (pb.x - po.x);
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (m >= 2 && turn(h[m - 2], h[m - 1], static_cast<int>(i)) <= 0) --m;
        h[m++] = static_cast<int>(i);
    }
    for (std::size_t i = p.size() - 1, t = m + 1; i > 0; --i) {
        while (m >= t && turn(h[m - 2], h[m - 1], static_cast<int>(i - 1)) <= 0) --m;
        h[m++] = static_cast<int>(i - 1);
    }
    --m;  // the first point again
    PlainCone c;
    c.rays.reserve(m);
    c.facets.reserve(m);
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3& a = g[static_cast<std::size_t>(p[static_cast<std::size_t>(h[i])].index)];
        const Vec3& b = g[static_cast<std::size_t>(p[static_cast<std::size_t>(h[i + 1 < m ? i + 1 : 0])].index)];
        c.rays.push_back(a);
        c.facets.push_back(a.cross(b));
    }
    return c;
}

void BM_cone_hull(benchmark::State& state) {
    const auto f = static_cast<Family>(state.range(0));
    const auto g = make(f, state.range(1));
    std::size_t facets = 0;
    for (auto _ : state) {
        const PlainCone c = plain_cone_hull(g);
        facets = c.facets.size();
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
BENCHMARK(BM_cone_hull)->Apply([](auto* b) { sizes(b, 100); });
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
        // Small cones beside the plain hull of the cone (the same job in doubles).
        const auto plain = rows.find("BM_cone_hull");
        if (plain == rows.end()) return;
        std::printf("\nSmall cones: ratios (time / time of the plain hull of the cone: the chart found, the"
                    " rays and facets listed, in doubles); facets found\n");
        std::printf("%-28s %8s %13s %11s %9s  %s\n", "family", "n", "plain hull ms", "momentlab", "ratio",
                    "facets: ours / plain hull / expected");
        for (const auto& [key, hull] : plain->second) {
            const auto it = ours.find(key);
            if (it == ours.end()) continue;
            auto expected = expected_facets(static_cast<Family>(key.first), key.second);
            if (expected < 0) expected = static_cast<std::int64_t>(rows.at("BM_hull2d").at(key).facets);
            std::printf("%-28s %8lld %13.4g %11.4g %9.2f  %.0f / %.0f / %lld\n", kFamilyNames[key.first],
                        static_cast<long long>(key.second), hull.ms, it->second.ms, it->second.ms / hull.ms,
                        it->second.facets, hull.facets, static_cast<long long>(expected));
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
