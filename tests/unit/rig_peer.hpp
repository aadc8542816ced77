// Independent peer ("second algorithm") for the rig dynamics of model.md, section
// "Rig dynamics: mass and system stiffness": a non-smooth time-stepping scheme, written without
// reference to the event-driven solver, against which that solver is cross-checked.
//
//   X'' = (2πΩ)² [κ (βφ − X) − s] + 4π ζ Ω √κ (β − X'),   s = X − X_c = stop operator of X in [−n, n].
//
// Scheme (Moreau–Jean type, θ = 1/2): with Y = X − βφ, U = X' − β (so the drive is periodic),
// the smooth part is the trapezoidal rule (= Newmark average acceleration for this linear ODE),
//   Y1 = Y0 + h/2 (U0 + U1),  U1 = U0 + h/2 (F0 + F1),  F = −a κ Y − a s − b U,
// and s1 is implicit through the catch-up (projection) form of the sweeping process,
//   s1 = clamp(s0 + (X1 − X0), −n(φ1), n(φ1)).
// The step equation A·d + c·s1(d) = R (d = Y1 − Y0) is strictly monotone and piecewise linear in d,
// so it is solved exactly (stick branch, else the clamped branch it overshoots into): no iteration.
// Touch-down (n rises from 0 inside a step) is located by bisection on n and only the part of the
// step's X increment after it loads the contact; without this the stress-free re-forming rule costs
// an O(h) offset of s over the whole following stick phase.
// Error: second order on smooth arcs; stick/slip switches fall between grid points, which costs
// O(h²) per switch when n is continuous (s, X, X' continuous there). A jump of n off the grid
// (square, sawtooth) is projected at the next grid point: O(h). The fractions are counted per
// step, so they are O(h) in any case. Observed for μ̄ (long double, 2^14..2^17 steps): order ≈ 2–3.5
// (triangle, flight and touch-down) and ≈ 1.7–2.5 (sine, no flight); not monotone from step to step.
// μ̄ = ∫s/∫n by the periodic trapezoid on the same grid; a step counts as flight if n(φ1) = 0,
// as slip if the projection was active (contact point moved), else as stick.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace vibrofric::test {

template <class T>
struct PeerResult {
    T mu, stick_fraction, slip_fraction, flight_fraction;
    std::size_t periods;
    // On the last period's grid: the share of steps that slipped backward (s clamped at −n), the
    // amplitude (max − min)/2 of Y, the largest distance the contact point X_c moved backward in
    // one contiguous backward-slip phase (a phase running across the period's end is joined), and
    // the transient's contraction per period: exp of the least-squares slope of log(change_p)
    // over the periods whose change lies in [1e-11, 1e-4] (the largest Floquet modulus where it
    // dominates the approach; a complex pair's rotation averages out over the periods; 0 where
    // fewer than six periods qualify).
    T backward_fraction, amplitude, largest_backward_slip, contraction;
    T state_y, state_u, state_s;  // the settled state at φ = 0 (U = X' − β)
};

// The scheme's one-period map on a fixed grid of M steps: (Y, U, s) at φ = 0 to the same at φ = 1,
// with the period's sums and counts (the peer's transient and its Floquet multipliers use it).
template <class T, class N>
class PeerMap {
 public:
    struct State {
        T Y, U, s;
    };
    struct Period {
        T sum_s = 0, sum_n = 0, stick = 0, slip = 0, flight = 0, backward = 0;
        T y_min = 0, y_max = 0, largest_back = 0;
    };

    PeerMap(N n, T beta, T kappa, T Omega, T zeta, std::size_t steps_per_period)
        : n_(n), beta_(beta), kappa_(kappa), M_(steps_per_period) {
        using std::sqrt;
        if (steps_per_period < 2) throw std::invalid_argument("rig_peer: steps_per_period < 2");
        const T pi = T(3.14159265358979323846264338327950288L);
        h_ = T(1) / T(M_);
        a_ = (2 * pi * Omega) * (2 * pi * Omega);
        b_ = 4 * pi * zeta * Omega * sqrt(kappa);
        A_ = 2 / h_ + h_ / 2 * a_ * kappa + b_;
        c_ = h_ / 2 * a_;
        nv_.resize(M_ + 1);
        for (std::size_t k = 0; k <= M_; ++k) nv_[k] = n(T(k) / T(M_));
        nv_[M_] = nv_[0];  // periodic grid: n(1) = n(0)
    }

    std::size_t steps() const { return M_; }

    Period period(State& x) const {
        const T h = h_, a = a_, b = b_, A = A_, c = c_, beta = beta_, kappa = kappa_;
        const std::size_t M = M_;
        T Y = x.Y, U = x.U, s = x.s;
        Period out;
        out.y_min = out.y_max = Y;
        T run = 0, first_run = -1;
        for (std::size_t k = 0; k < M; ++k) {
            const T n1 = nv_[k + 1];
            const T F0 = -a * kappa * Y - a * s - b * U;
            const T R = 2 * U + h / 2 * F0 - h / 2 * a * kappa * Y + h / 2 * b * U;
            // Touch-down inside the step: the contact forms stress-free at φ_td (bisection on n),
            // so only the fraction θ of the step's (linear) X increment loads it.
            T th = 1;
            if (nv_[k] <= 0 && n1 > 0) {
                T lo = T(k) / T(M), hi = T(k + 1) / T(M);
                for (int i = 0; i < 80 && lo < hi; ++i) { const T mid = (lo + hi) / 2; (n_(mid) > 0 ? hi : lo) = mid; }
                th = (T(k + 1) / T(M) - hi) / h;
            }
            T d = (R - c * (s + th * beta * h)) / (A + c * th);  // stick branch: s1 = s + θ(d + βh)
            T s1 = s + th * (d + beta * h);
            bool moved = false, back = false;
            if (s1 > n1)       { s1 = n1;  d = (R - c * n1) / A; moved = true; }
            else if (s1 < -n1) { s1 = -n1; d = (R + c * n1) / A; moved = true; back = true; }
            const T U1 = 2 * d / h - U;
            out.sum_s += (s + s1) / 2;
            out.sum_n += (nv_[k] + n1) / 2;
            if (n1 <= 0) out.flight += 1; else if (moved) out.slip += 1; else out.stick += 1;
            // X_c = X − s moves by (d + βh) − (s1 − s) in the step.
            const T dxc = d + beta * h - (s1 - s);
            if (back && n1 > 0) {
                out.backward += 1;
                run += dxc < 0 ? -dxc : T(0);
            } else {
                if (first_run < 0) first_run = run;  // the phase the period began in (0: none)
                out.largest_back = std::max(out.largest_back, run);
                run = 0;
            }
            Y += d; U = U1; s = s1;
            out.y_min = std::min(out.y_min, Y);
            out.y_max = std::max(out.y_max, Y);
        }
        // a backward phase still open at the period's end continues into the next one's first
        if (run > 0) out.largest_back = std::max(out.largest_back, first_run < 0 ? run : run + first_run);
        x = {Y, U, s};
        return out;
    }

 private:
    N n_;
    T beta_, kappa_;
    std::size_t M_;
    T h_, a_, b_, A_, c_;
    std::vector<T> nv_;
};

template <class T, class N>
PeerResult<T> rig_peer(N n, T beta, T kappa, T Omega, T zeta, std::size_t steps_per_period,
                       std::size_t max_periods = 2000, T settle = T(1e-12)) {
    using std::abs;
    const PeerMap<T, N> map(n, beta, kappa, Omega, zeta, steps_per_period);
    typename PeerMap<T, N>::State x{0, 0, 0};  // X = 0, X' = β, stress-free contact
    std::vector<T> changes;
    for (std::size_t p = 1; p <= max_periods; ++p) {
        const auto start = x;
        const auto q = map.period(x);
        const T change = std::max({abs(x.Y - start.Y), abs(x.U - start.U), abs(x.s - start.s)});
        changes.push_back(change);
        if (change < settle) {
            const T m = T(map.steps());
            T contraction = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, count = 0;
            for (std::size_t k = 0; k < changes.size(); ++k)
                if (changes[k] >= T(1e-11) && changes[k] <= T(1e-4)) {
                    const T u = T(k), y = std::log(changes[k]);
                    sx += u; sy += y; sxx += u * u; sxy += u * y; count += 1;
                }
            if (count >= 6) contraction = std::exp((count * sxy - sx * sy) / (count * sxx - sx * sx));
            return {q.sum_s / q.sum_n, q.stick / m, q.slip / m, q.flight / m, p, q.backward / m, (q.y_max - q.y_min) / 2,
                    q.largest_back, contraction, x.Y, x.U, x.s};
        }
    }
    throw std::runtime_error("rig_peer: no periodic state within max_periods");
}

}  // namespace vibrofric::test
