// Times Versor (github.com/wolftype/versor, C++ templates) on the six operations of
// benches/peers/compare.sh, the same way benches/batch_timing.rs times ours: batches of 256
// independent operands, `REPS` passes per round, median over rounds, ns per operation.
// Only this harness is ours; Versor's headers come from the checkout in $VERSOR_DIR.
// Build: g++ -O3 -std=c++14 -DVSR_PRECISION_DOUBLE [-march=native] -I$VERSOR_DIR/include versor.cpp
// (without -DVSR_PRECISION_DOUBLE Versor's scalar is float: compare.sh times that build too,
// for reference only).
#include <vsr/space/vsr_cga3D_types.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace vsr::cga;
static const int N = 256, REPS = 4000, ROUNDS = 15;

template <class T> static void escape(T* p) { asm volatile("" : : "g"(p) : "memory"); }

// The same operands as batch_timing.rs: points on a deterministic spread.
static double coord(int i, int k, double seed) {
    double t = seed + i;
    double v[3] = {3.0 * std::sin(1.3 * t), 2.0 * std::cos(0.7 * t), std::sin(2.9 * t) - 0.5};
    return v[k];
}
static Pnt point(int i, double seed) {
    double x = coord(i, 0, seed), y = coord(i, 1, seed), z = coord(i, 2, seed);
    return Pnt(x, y, z, 1.0, 0.5 * (x * x + y * y + z * z));
}

template <class F> static double median_ns(F f) {
    std::vector<double> r;
    for (int round = 0; round < ROUNDS; ++round) {
        auto t0 = std::chrono::steady_clock::now();
        for (int rep = 0; rep < REPS; ++rep) f();
        auto t1 = std::chrono::steady_clock::now();
        r.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(REPS) * N));
    }
    std::sort(r.begin(), r.end());
    return r[ROUNDS / 2];
}

int main() {
    std::vector<Pnt> a(N), b(N), c(N);
    std::vector<Dll> lines(N);
    std::vector<Dls> spheres(N);
    std::vector<Cir> c1(N), c2(N);
    std::vector<Mot> m1(N), m2(N);
    std::vector<Rot> r1(N), r2(N);
    for (int i = 0; i < N; ++i) {
        a[i] = point(i, 0.0); b[i] = point(i, 100.0); c[i] = point(i, 200.0);
        // A dual line through a and b, a dual sphere about c: built by Versor's products.
        lines[i] = (a[i] ^ b[i] ^ Inf(1)).dual();
        spheres[i] = c[i] - Inf(0.5 * (1.0 + 0.1 * (i % 7)));
        c1[i] = a[i] ^ b[i] ^ c[i];
        c2[i] = b[i] ^ c[i] ^ point(i, 300.0);
        double s = std::sin(0.01 * i), k = std::cos(0.01 * i);
        r1[i] = Rot(k, 0.6 * s, -0.48 * s, 0.64 * s);
        r2[i] = Rot(s, 0.36 * k, 0.8 * k, -0.48 * k);
        m1[i] = Mot(k, 0.6 * s, -0.48 * s, 0.64 * s, 0.3 * i, -0.2, 0.1 * s, 0.05 * k);
        m2[i] = Mot(s, 0.36 * k, 0.8 * k, -0.48 * k, 0.1, 0.7 * s, -0.2 * i, 0.02 * s);
    }
    std::vector<Par> pairs(N);
    std::vector<Cir> circles(N);
    std::vector<Pnt> moved(N);
    std::vector<decltype(c1[0] * c2[0])> evens(N);
    std::vector<decltype(m1[0] * m2[0])> motors(N);
    std::vector<decltype(r1[0] * r2[0])> rotors(N);

    std::printf("line_meet_sphere %.3f\n", median_ns([&] {
        escape(lines.data()); escape(spheres.data());
        for (int i = 0; i < N; ++i) pairs[i] = (lines[i] ^ spheres[i]).dual();
        escape(pairs.data());
    }));
    std::printf("circle_from_3_points %.3f\n", median_ns([&] {
        escape(a.data()); escape(b.data()); escape(c.data());
        for (int i = 0; i < N; ++i) circles[i] = a[i] ^ b[i] ^ c[i];
        escape(circles.data());
    }));
    std::printf("motor_on_point %.3f\n", median_ns([&] {
        escape(m1.data()); escape(a.data());
        for (int i = 0; i < N; ++i) moved[i] = a[i].spin(m1[i]);
        escape(moved.data());
    }));
    std::printf("circle_times_circle %.3f\n", median_ns([&] {
        escape(c1.data()); escape(c2.data());
        for (int i = 0; i < N; ++i) evens[i] = c1[i] * c2[i];
        escape(evens.data());
    }));
    std::printf("motor_times_motor %.3f\n", median_ns([&] {
        escape(m1.data()); escape(m2.data());
        for (int i = 0; i < N; ++i) motors[i] = m1[i] * m2[i];
        escape(motors.data());
    }));
    std::printf("rotor_times_rotor %.3f\n", median_ns([&] {
        escape(r1.data()); escape(r2.data());
        for (int i = 0; i < N; ++i) rotors[i] = r1[i] * r2[i];
        escape(rotors.data());
    }));
    return 0;
}
