// Times klein (github.com/jeremyong/klein, C++ with SSE, f32 only) on the operations of
// benches/peers/klein.sh, the same way benches/pga_timing.rs times ours: a motor moving 1e6
// points through klein's array form `m(in, out, count)` (which precomputes the motor once),
// and over batches of 256 operands the motor product, the join of two points and the meets of
// two and three planes; the median over rounds, in ns per operation; and, as the floor of the
// memory path, a plain copy of the 1e6 points (`klein-copy`). Prints `operation klein ns`
// lines. Only this harness is ours; klein's headers come from the checkout in $KLEIN_DIR.
// Build: g++ -O3 -march=native -std=c++17 -I$KLEIN_DIR/public klein.cpp
#include <klein/klein.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

static const int BATCH = 256, POINTS = 1000000, ROUNDS = 15;

template <class T> static void escape(T* p) { asm volatile("" : : "g"(p) : "memory"); }

// The same deterministic spread as pga_timing.rs.
static float coord(int i, int k, double seed) {
    double t = seed + i;
    double v[3] = {3.0 * std::sin(1.3 * t), 2.0 * std::cos(0.7 * t), std::sin(2.9 * t) - 0.5};
    return float(v[k]);
}
static kln::point point(int i, double seed) { return kln::point(coord(i, 0, seed), coord(i, 1, seed), coord(i, 2, seed)); }
static kln::plane plane(int i, double seed) {
    float a = coord(i, 0, seed), b = coord(i, 1, seed), c = coord(i, 2, seed), n = std::sqrt(a * a + b * b + c * c);
    return kln::plane(a / n, b / n, c / n, coord(i, 0, seed + 7.0));
}
// A unit motor, a rotation about the axis (0.6, −0.48, 0.64) then a translation, as ours.
static kln::motor motor(int i) {
    float angle = 2.0f * float(0.01 * i + 0.3);
    return kln::translator(std::sqrt(0.56f), -0.6f, 0.4f, -0.2f) * kln::rotor(angle, 0.6f, -0.48f, 0.64f);
}

template <class F> static double median_ns(int ops, int reps, F f) {
    std::vector<double> r;
    for (int round = 0; round < ROUNDS; ++round) {
        auto t0 = std::chrono::steady_clock::now();
        for (int rep = 0; rep < reps; ++rep) f();
        auto t1 = std::chrono::steady_clock::now();
        r.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(reps) * ops));
    }
    std::sort(r.begin(), r.end());
    return r[ROUNDS / 2];
}

int main() {
    std::vector<kln::point> in(POINTS), out(POINTS);
    for (int i = 0; i < POINTS; ++i) in[i] = point(i, 0.0);
    kln::motor m = motor(1);
    std::printf("motor_points klein %.3f\n", median_ns(POINTS, 3, [&] {
        escape(in.data());
        m(in.data(), out.data(), POINTS);
        escape(out.data());
    }));
    // The floor of the memory path: the same 16 MB read and written with no arithmetic.
    std::printf("motor_points klein-copy %.3f\n", median_ns(POINTS, 3, [&] {
        escape(in.data());
        std::copy(in.begin(), in.end(), out.begin());
        escape(out.data());
    }));

    std::vector<kln::motor> m1(BATCH), m2(BATCH), mo(BATCH);
    std::vector<kln::point> p1(BATCH), p2(BATCH), po(BATCH);
    std::vector<kln::plane> q1(BATCH), q2(BATCH), q3(BATCH);
    std::vector<kln::line> lo(BATCH);
    for (int i = 0; i < BATCH; ++i) {
        m1[i] = motor(i); m2[i] = motor(i + 300);
        p1[i] = point(i, 0.0); p2[i] = point(i, 100.0);
        q1[i] = plane(i, 0.0); q2[i] = plane(i, 100.0); q3[i] = plane(i, 200.0);
    }
    auto batch = [&](const char* name, auto op, auto* o) {
        std::printf("%s klein %.3f\n", name, median_ns(BATCH, 4000, [&] {
            escape(m1.data()); escape(p1.data()); escape(q1.data());
            for (int i = 0; i < BATCH; ++i) o[i] = op(i);
            escape(o);
        }));
    };
    batch("motor_motor", [&](int i) { return m1[i] * m2[i]; }, mo.data());
    batch("join", [&](int i) { return p1[i] & p2[i]; }, lo.data());
    batch("meet", [&](int i) { return q1[i] ^ q2[i]; }, lo.data());
    batch("meet3", [&](int i) { return q1[i] ^ q2[i] ^ q3[i]; }, po.data());
}
