// bench_contact: contact modes and every applied-wrench set E_i for n = 10 .. 10^5 contacts,
// and `query` throughput on scenes of 2 .. 8 contacts beside one solve of the same question
// as the standard acceleration-level planar Coulomb LCP with Siconos Numerics' Lemke solver
// (two friction directions per contact; docs/benchmarks.md). `make bench` prints the ratios.
#include <benchmark/benchmark.h>

#include <siconos/numerics/LCP_Solvers.h>
#include <siconos/numerics/LinearComplementarityProblem.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/lcp_cst.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <vector>

#include "momentlab/mechanics/dynamics.hpp"

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

// The same question as an LCP: z = (lambda_n, lambda_+, lambda_-, sigma), size 4n,
//   w_n = N' a >= 0 _|_ lambda_n,   w_+ = sigma + T' a >= 0 _|_ lambda_+,
//   w_- = sigma - T' a >= 0 _|_ lambda_-,   w_s = mu lambda_n - lambda_+ - lambda_- >= 0 _|_ sigma,
// with a = M^-1 (e + sum_j lambda_n N_j + (lambda_+ - lambda_-) T_j).
void BM_lemke(benchmark::State& state) {
    std::mt19937_64 rng(7 + static_cast<std::uint64_t>(state.range(0)));
    const Scene s = random_scene(static_cast<int>(state.range(0)), rng);
    const auto w = random_wrenches(rng);
    const int n = static_cast<int>(s.contacts.size()), size = 4 * n;
    const Mat3 minv = inertia_at_origin(*s.body).inverse();
    Eigen::MatrixXd d(3, 3 * n);  // wrench columns: N_j, T_j, -T_j
    for (int j = 0; j < n; ++j) {
        d.col(j) = s.contacts[static_cast<std::size_t>(j)].normal_wrench();
        d.col(n + j) = s.contacts[static_cast<std::size_t>(j)].tangent_wrench();
        d.col(2 * n + j) = -d.col(n + j);
    }
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size, size);
    m.topLeftCorner(3 * n, 3 * n) = d.transpose() * minv * d;
    for (int j = 0; j < n; ++j) {
        m(n + j, 3 * n + j) = 1;
        m(2 * n + j, 3 * n + j) = 1;
        m(3 * n + j, j) = s.contacts[static_cast<std::size_t>(j)].mu;
        m(3 * n + j, n + j) = -1;
        m(3 * n + j, 2 * n + j) = -1;
    }
    NumericsMatrix* nm = NM_create(NM_DENSE, size, size);
    for (int c = 0; c < size; ++c) {
        for (int r = 0; r < size; ++r) nm->matrix0[c * size + r] = m(r, c);  // column-major
    }
    std::vector<double> q(static_cast<std::size_t>(size), 0.0), z(q), ww(q);
    LinearComplementarityProblem problem{size, nm, q.data()};
    SolverOptions* options = solver_options_create(SICONOS_LCP_LEMKE);
    std::size_t i = 0;
    int failures = 0;
    for (auto _ : state) {
        const Eigen::VectorXd qe = d.transpose() * minv * w[i++ & 1023];
        for (int k = 0; k < 3 * n; ++k) q[static_cast<std::size_t>(k)] = qe(k);
        int info = 0;
        lcp_lexicolemke(&problem, z.data(), ww.data(), &info, options);
        failures += info != 0;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["failures"] = failures;
    solver_options_delete(options);
    NM_free(nm);
}
BENCHMARK(BM_lemke)->DenseRange(2, 8, 2);

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
