// Eqs. 7-13: the paper's "after expanding and rearranging", for a GENERAL waveform.
// Physical symbols mu0, k_z, k_x, v0, f, A, ubar, t1, t2 are kept; the waveform enters only through
// w1 = w(phi1), w2 = w(phi2), I = int_{phi1}^{phi2} w dphi and Wbar = int_0^1 w dphi (zero mean).
// From F_z = k_z (ubar + A w(f t)) (Eq. 2, no clipping), F_stick (Eq. 7), beta (Eq. 5) and t = phi/f:
//   Eq. 4 (from Eq. 3), Eq. 8 (end of stick), Eq. 10 -> Eq. 11 with Psi of Eq. 12, Eq. 13 via Eq. 9,
// for K = 1, 2, 3 stick phases per period; explicit waves (tri, tri2, a C^1 piecewise-quadratic wave)
// integrated by GiNaC in time; controls: ramp sign, factor 1/2, non-zero mean, clipped triangle.
#include "engine.hpp"
using namespace proofs;

namespace {

struct Sym {
  symbol mu0{"mu0"}, kz{"k_z"}, kx{"k_x"}, v0{"v0"}, f{"f"}, A{"A"}, ub{"ubar"}, t{"t"};
  symbol W{"W"};        // placeholder: the value w(f t) (or w(phi)) inside an integrand
  symbol Wbar{"Wbar"};  // int_0^1 w dphi (zero for a zero-mean waveform)
};
Sym& S() { static Sym s; return s; }

// int_lo^hi e d(var) for e affine in the placeholder W (the waveform at the integration variable).
// The W-free part is integrated by GiNaC; the W part is (its coefficient, which must not depend on
// var) times Wint, the integral of the waveform over [lo, hi] in that variable. For time:
// int_{t_a}^{t_b} w(f t) dt = (1/f) int_{f t_a}^{f t_b} w(phi) dphi  (substitution phi = f t).
ex integrate_affine(const ex& e0, const symbol& var, const ex& lo, const ex& hi, const ex& Wint) {
  ex e = expand(e0);
  if (e.degree(S().W) > 1) throw std::runtime_error("integrand not affine in w");
  ex c1 = e.coeff(S().W, 1), c0 = e.coeff(S().W, 0);
  if (!normal(diff(c1, var)).is_zero()) throw std::runtime_error("coefficient of w depends on the variable");
  return integral(var, lo, hi, c0).eval_integ() + c1 * Wint;
}

// Eq. 12, expanded: int_{p1}^{p2} (w - w1 - beta (phi - p1)) dphi with int w = I.
ex psi12(const ex& w1, const ex& I, const ex& p1, const ex& p2) {
  return integrate_affine(S().W - w1 - B() * (PHI() - p1), PHI(), p1, p2, I);
}

// One piece of an explicit wave: w(phi) = expression in PHI() on [x0, x1].
struct Piece { ex x0, x1, w; };
// One interval of the period partition: phases [p0, p1] inside piece pc; stick = index of the
// stick phase (F_x = F_stick of that phase) or -1 (slip, F_x = mu0 F_z).
struct Interval { Piece pc; ex p0, p1; int stick; };
struct StickPhase { ex phi1, phi2, w1; };  // onset, end and w(phi1) (explicit)

struct Explicit {
  ex FzMean, FxMean, dFx, Psi_general, I_sum;
};

// Everything by direct time integration of the explicit w(f t) (GiNaC antiderivatives).
Explicit explicit_wave(const std::vector<Interval>& iv, const std::vector<StickPhase>& st, const exmap& to_beta,
                       const ex& Fz_t /* F_z(t) with W as placeholder */) {
  Sym& s = S();
  Explicit r;
  r.FzMean = 0; r.FxMean = 0;
  std::vector<ex> I(st.size(), ex(0));
  for (auto& i : iv) {
    ex wt = i.pc.w.subs(PHI() == s.f * s.t);  // w(f t) on this piece
    ex Fz = Fz_t.subs(s.W == wt);
    ex Fx = Fz * s.mu0;
    if (i.stick >= 0) {
      const StickPhase& p = st[i.stick];
      ex t1 = p.phi1 / s.f;
      Fx = s.mu0 * Fz_t.subs(s.W == p.w1) + s.kx * s.v0 * (s.t - t1);  // Eq. 7
      I[i.stick] += integral(PHI(), i.p0, i.p1, i.pc.w).eval_integ();
    }
    r.FzMean += s.f * integral(s.t, i.p0 / s.f, i.p1 / s.f, Fz).eval_integ();
    r.FxMean += s.f * integral(s.t, i.p0 / s.f, i.p1 / s.f, Fx).eval_integ();
  }
  // expand first: it merges powers of algebraic numbers (sqrt 2 in the quadratic wave), normal does not
  r.FzMean = normal(expand(r.FzMean.subs(to_beta)));
  r.FxMean = normal(expand(r.FxMean.subs(to_beta)));
  r.dFx = normal(expand(s.mu0 * r.FzMean - r.FxMean));
  r.Psi_general = 0; r.I_sum = 0;
  for (size_t k = 0; k < st.size(); ++k) {
    r.Psi_general += psi12(st[k].w1, I[k], st[k].phi1, st[k].phi2);  // the general formula, explicit inputs
    r.I_sum += I[k];
  }
  r.Psi_general = normal(expand(r.Psi_general));
  return r;
}

}  // namespace

int main() {
  Checker ck;
  Sym& s = S();
  const ex beta = B();
  const ex& mu0 = s.mu0; const ex& kz = s.kz; const ex& kx = s.kx; const ex& v0 = s.v0;
  const ex& f = s.f; const ex& A = s.A; const ex& ub = s.ub; const ex& t = s.t; const ex& W = s.W;
  const ex T = 1 / f;
  const ex alpha = A / ub;
  const exmap to_beta = {{kx, beta * mu0 * kz * A * f / v0}};  // Eq. 5 solved for k_x
  const ex Fz_t = kz * (ub + A * W);                             // Eq. 2, F_z = k_z u_z (no clipping)

  // ------------------------------------------------------------------ 1. one stick phase
  std::cout << "== general waveform, one stick phase per period\n";
  symbol t1("t1"), t2("t2"), phi1("phi1"), phi2("phi2"), w1("w1"), w2("w2"), I("I"), dW("dW");
  const exmap to_phase = {{t1, phi1 / f}, {t2, phi2 / f}};  // phi = f t
  auto to_dimless = [&](const ex& e) { return normal(e.subs(to_beta).subs(to_phase)); };

  // Eq. 4 from Eq. 3: while slipping F_x = mu0 F_z, so the spring elongation F_x/k_x changes at
  // mu0 k_z A f w'(f t)/k_x (Eq. 3); stick starts where this reaches the pulling velocity v0.
  ex wprime1 = lsolve(mu0 * kz * A * f * dW / kx == v0, dW);
  std::cout << "     Eq. 3 = v0 solved for w'(phi1): " << wprime1 << "\n";
  ck.zero(to_dimless(wprime1) - beta, "Eq. 4: stick onset where w'(phi1) = beta");
  ck.zero(diff(wprime1, s.ub), "the onset condition does not contain ubar");

  const ex Fz1 = Fz_t.subs(W == w1);                       // F_z(t1)
  const ex Fstick = mu0 * Fz1 + kx * v0 * (t - t1);        // Eq. 7
  // Eq. 8: the stick ends where F_stick meets mu0 F_z
  ex w2_sol = lsolve(Fstick.subs(t == t2) == mu0 * Fz_t.subs(W == w2), w2);
  std::cout << "     F_stick(t2) = mu0 F_z(t2) solved for w2: " << w2_sol << "\n";
  ck.zero(to_dimless(w2_sol) - (w1 + beta * (phi2 - phi1)), "Eq. 8: beta (phi2 - phi1) = w2 - w1");
  ck.zero(diff(w2_sol, s.ub), "the stick end (Eq. 8) does not contain ubar");
  ck.nonzero(to_dimless(w2_sol) - (w1 - beta * (phi2 - phi1)), "Eq. 8 with -beta");

  // Eq. 10
  const ex dFx = normal(integrate_affine(mu0 * Fz_t - Fstick, s.t, t1, t2, I / f) / T);
  std::cout << "     Eq. 10: Delta F_x = " << dFx << "\n";
  const ex dFx_d = to_dimless(dFx);
  const ex Psi = normal(psi12(w1, I, phi1, phi2));  // Eq. 12, integrated
  std::cout << "     Eq. 12: Psi = " << Psi << "\n";
  ck.zero(dFx_d - mu0 * kz * A * Psi, "Eq. 11: Delta F_x = mu0 k_z A Psi_w(beta), Psi from Eq. 12");
  ck.zero(Psi - (I - w1 * (phi2 - phi1) - beta * pow(phi2 - phi1, 2) / 2),
          "Eq. 12 = I - w1 (phi2 - phi1) - beta (phi2 - phi1)^2/2");
  ck.zero(diff(dFx, s.ub), "Delta F_x (Eq. 10) does not depend on ubar (the mu0 k_z ubar terms cancel)");
  ck.zero(diff(Psi, s.ub), "Psi does not depend on ubar (nor do its inputs phi1, phi2: Eqs. 4, 8 above)");
  // with Eq. 8: the area between w and its chord
  ck.zero(Psi - (I - (w1 + w2) * (phi2 - phi1) / 2).subs(w2 == w1 + beta * (phi2 - phi1)),
          "with Eq. 8: Psi = I - (w1 + w2)(phi2 - phi1)/2 (area between w and the chord)");

  // Eq. 13 through Eq. 9: F_x = F_stick on [t1, t2] and mu0 F_z on the slip part [t2, t1 + T]
  const ex FzMean = normal(integrate_affine(Fz_t, s.t, 0, T, s.Wbar / f) / T);
  const ex FxMean = normal((integrate_affine(Fstick, s.t, t1, t2, I / f) +
                            integrate_affine(mu0 * Fz_t, s.t, t2, t1 + T, (s.Wbar - I) / f)) / T);
  std::cout << "     <F_z> = " << FzMean << ",  <F_x> = " << FxMean << "\n";
  ck.zero(FxMean - (mu0 * FzMean - dFx), "Eq. 9 = <mu0 F_z> - Delta F_x (F_x differs from mu0 F_z only while sticking)");
  ck.zero(FzMean.subs(s.Wbar == 0) - kz * ub, "<F_z> = k_z ubar (zero mean, no clipping)");
  const ex mubar = normal(to_dimless(FxMean / FzMean).subs(s.Wbar == 0));
  ck.zero(mubar - (mu0 - dFx_d / (kz * ub)), "Eq. 13 (middle): mu = mu0 - Delta F_x/(k_z ubar)");
  ck.zero(mubar - mu0 * (1 - alpha * Psi), "Eq. 13: mu = mu0 (1 - alpha Psi_w(beta)), alpha = A/ubar");
  // controls
  ck.nonzero(to_dimless(FxMean / FzMean) - mu0 * (1 - alpha * Psi),
             "Eq. 13 without the zero mean (Wbar kept): <F_z> = k_z (ubar + A Wbar)");
  {
    const ex Fwrong = mu0 * Fz1 - kx * v0 * (t - t1);  // ramp with the wrong sign
    ex d = to_dimless(integrate_affine(mu0 * Fz_t - Fwrong, s.t, t1, t2, I / f) / T);
    ck.nonzero(d - mu0 * kz * A * Psi, "F_stick = mu0 F_z(t1) - k_x v0 (t - t1) (wrong sign of the ramp)");
    ck.nonzero(dFx_d - mu0 * kz * A * (I - w1 * (phi2 - phi1) - beta * pow(phi2 - phi1, 2)),
               "Psi = I - w1 (phi2 - phi1) - beta (phi2 - phi1)^2 (factor 1/2 dropped)");
    ck.nonzero(mubar - mu0 * (1 - Psi / alpha), "mu = mu0 (1 - Psi/alpha)");
  }

  // ------------------------------------------------------------------ 2. K stick phases
  for (int K = 1; K <= 3; ++K) {
    std::cout << "== general waveform, K = " << K << " stick phases per period\n";
    std::vector<symbol> T1, T2, P1, P2, W1, Ik, Jk;
    for (int k = 1; k <= K; ++k) {
      std::string i = std::to_string(k);
      T1.emplace_back("t1_" + i); T2.emplace_back("t2_" + i); P1.emplace_back("phi1_" + i);
      P2.emplace_back("phi2_" + i); W1.emplace_back("w1_" + i); Ik.emplace_back("I_" + i); Jk.emplace_back("J_" + i);
    }
    // the period t1_1 <= t2_1 <= t1_2 <= ... <= t2_K <= t1_1 + T: stick [t1_k, t2_k], slip [t2_k, t1_{k+1}];
    // I_k, J_k the phase integrals of w over the stick and slip intervals, sum_k (I_k + J_k) = Wbar.
    ex Jlast = s.Wbar;
    for (int k = 0; k < K; ++k) Jlast -= Ik[k];
    for (int k = 0; k + 1 < K; ++k) Jlast -= Jk[k];
    exmap ph = to_beta;
    for (int k = 0; k < K; ++k) { ph[T1[k]] = P1[k] / f; ph[T2[k]] = P2[k] / f; }
    ex Fx_int = 0, Fz_int = integrate_affine(Fz_t, s.t, 0, T, s.Wbar / f), dF = 0, PsiSum = 0;
    for (int k = 0; k < K; ++k) {
      ex Fst = mu0 * Fz_t.subs(W == W1[k]) + kx * v0 * (t - T1[k]);
      ex next = (k + 1 < K) ? ex(T1[k + 1]) : T1[0] + T;
      Fx_int += integrate_affine(Fst, s.t, T1[k], T2[k], Ik[k] / f);
      Fx_int += integrate_affine(mu0 * Fz_t, s.t, T2[k], next, ((k + 1 < K) ? ex(Jk[k]) : Jlast) / f);
      dF += integrate_affine(mu0 * Fz_t - Fst, s.t, T1[k], T2[k], Ik[k] / f) / T;  // Eq. 10 per phase
      PsiSum += psi12(W1[k], Ik[k], P1[k], P2[k]);
    }
    ex FxM = normal(Fx_int / T), FzM = normal(Fz_int / T);
    ex dFd = normal(dF.subs(ph)), PsiS = normal(PsiSum);
    ck.zero(normal((mu0 * FzM - FxM).subs(ph)) - mu0 * kz * A * PsiS,
            "K = " + std::to_string(K) + ": <mu0 F_z> - <F_x> = mu0 k_z A sum_k Psi_k (per-phase Eq. 12 areas)");
    ck.zero(dFd - mu0 * kz * A * PsiS, "K = " + std::to_string(K) + ": Eq. 10 summed over the phases = mu0 k_z A sum_k Psi_k");
    ck.zero(diff(dFd, s.ub), "K = " + std::to_string(K) + ": Delta F_x does not depend on ubar");
    ex mu = normal((FxM / FzM).subs(ph).subs(s.Wbar == 0));
    ck.zero(mu - mu0 * (1 - alpha * PsiS), "K = " + std::to_string(K) + ": Eq. 13 with Psi = sum_k Psi_k");
    if (K > 1) {
      ex PsiOne = normal(psi12(W1[0], Ik[0], P1[0], P2[0]));
      ck.nonzero(mu - mu0 * (1 - alpha * PsiOne), "K = " + std::to_string(K) + ": only the first phase's area");
    }
  }

  // ------------------------------------------------------------------ 3. explicit waves
  // Each: events derived from the explicit w (Eq. 4 / kink at the minimum; end from F_stick = mu0 F_z),
  // all integrals done in time by GiNaC; compared with the general formula fed with the explicit
  // w1, w2, I, with the engine's int(n - s) and with the paper's closed form where there is one.
  const ex g = G();
  auto physical_end = [&](const Piece& pc, const ex& p1, const ex& w1v) {
    // stick end on a linear piece: F_stick(t2) = mu0 F_z(t2), solved for t2, returned as phase f t2
    symbol tt("tt");
    ex eq = mu0 * Fz_t.subs(W == w1v) + kx * v0 * (tt - p1 / f) == mu0 * Fz_t.subs(W == pc.w.subs(PHI() == f * tt));
    return normal((f * lsolve(eq, tt)).subs(to_beta));
  };
  auto report = [&](const std::string& name, const Explicit& r, const std::vector<StickPhase>& st) {
    std::cout << "-- " << name << "\n";
    for (auto& p : st) std::cout << "     stick from phi1 = " << p.phi1 << " to phi2 = " << p.phi2 << "\n";
    std::cout << "     <F_z> = " << r.FzMean << ",  Delta F_x = " << factor(r.dFx) << "\n";
    ck.zero(r.FzMean - kz * ub, name + ": <F_z> = k_z ubar by direct integration (zero mean)");
    ck.zero(r.dFx - mu0 * kz * A * r.Psi_general, name + ": Delta F_x (Eq. 10, integrated in t) = mu0 k_z A Psi (Eq. 12 with the explicit w1, I)");
    ck.zero(diff(r.dFx, s.ub), name + ": Delta F_x does not depend on ubar");
    ck.zero(normal(r.FxMean / r.FzMean) - mu0 * (1 - alpha * r.Psi_general), name + ": <F_x>/<F_z> = mu0 (1 - alpha Psi) (Eq. 13)");
  };
  {  // triangle, Eq. 16, ubar > A
    Regime R = make_regime("0 < beta < 4, gamma > 1", {{0, 1}, {4, 1}}, {{0, 1}});
    Piece up{0, numeric(1, 2), 4 * PHI() - 1}, dn{numeric(1, 2), 1, 3 - 4 * PHI()};
    // onset: the kink at the minimum (w' jumps from -4 to 4 > beta); w1 = -1
    ex p2 = physical_end(dn, 0, -1);
    ck.ok(decide(p2 - numeric(1, 2), R, "tri phi2 - 1/2") > 0 && decide(1 - p2, R, "tri 1 - phi2") > 0,
          "tri: the stick end " + ex_to_string(p2) + " lies on the falling flank (proved sign)");
    std::vector<StickPhase> st = {{0, p2, -1}};
    std::vector<Interval> iv = {{up, 0, numeric(1, 2), 0}, {dn, numeric(1, 2), p2, 0}, {dn, p2, 1, -1}};
    Explicit r = explicit_wave(iv, st, to_beta, Fz_t);
    report("tri (Eq. 16), 0 < beta < 4, ubar > A", r, st);
    ck.zero(r.Psi_general - (4 - beta) / (4 + beta), "tri: Psi = (4 - beta)/(4 + beta) (Eq. 17)");
    Result e = run(clip(wave("tri"), g, R), beta, R);
    ck.zero(r.Psi_general - e.Red, "tri: Psi = engine int(n - s), gamma > 1");
    ck.zero(dFx_d.subs(lst{w1 == -1, phi1 == 0, phi2 == p2, I == r.I_sum}) - r.dFx,
            "tri: the general Delta F_x with w1 = -1, phi1 = 0, phi2, I substituted = explicit Delta F_x");
  }
  {  // tri2: triangle of half period, two stick phases per period
    Regime R = make_regime("0 < beta < 8, gamma > 1", {{0, 1}, {8, 1}}, {{0, 1}});
    Piece u1{0, numeric(1, 4), 8 * PHI() - 1}, d1{numeric(1, 4), numeric(1, 2), 3 - 8 * PHI()};
    Piece u2{numeric(1, 2), numeric(3, 4), 8 * PHI() - 5}, d2{numeric(3, 4), 1, 7 - 8 * PHI()};
    ex a2 = physical_end(d1, 0, -1), b2 = physical_end(d2, numeric(1, 2), -1);
    ck.ok(decide(a2 - numeric(1, 4), R, "tri2 a2-1/4") > 0 && decide(numeric(1, 2) - a2, R, "tri2 1/2-a2") > 0 &&
              decide(b2 - numeric(3, 4), R, "tri2 b2-3/4") > 0 && decide(1 - b2, R, "tri2 1-b2") > 0,
          "tri2: both stick ends lie on their falling flanks (proved sign)");
    std::vector<StickPhase> st = {{0, a2, -1}, {numeric(1, 2), b2, -1}};
    std::vector<Interval> iv = {{u1, 0, numeric(1, 4), 0}, {d1, numeric(1, 4), a2, 0}, {d1, a2, numeric(1, 2), -1},
                                {u2, numeric(1, 2), numeric(3, 4), 1}, {d2, numeric(3, 4), b2, 1}, {d2, b2, 1, -1}};
    Explicit r = explicit_wave(iv, st, to_beta, Fz_t);
    report("tri2 (K = 2), 0 < beta < 8, ubar > A", r, st);
    Result e = run(clip(wave("tri2"), g, R), beta, R);
    ck.zero(r.Psi_general - e.Red, "tri2: Psi_1 + Psi_2 = engine int(n - s), gamma > 1");
    ck.nonzero(r.Psi_general - e.Red / 2, "tri2: a single phase's area as Psi");
  }
  {  // C^1 piecewise-quadratic wave (power:2 of the catalogue, shifted): w = 8u - 16u|u| on [-1/2, 1/2)
    Piece L{numeric(-1, 2), 0, 8 * PHI() + 16 * pow(PHI(), 2)}, Rr{0, numeric(1, 2), 8 * PHI() - 16 * pow(PHI(), 2)};
    // Eq. 4: w' = beta on the piece where w' increases
    ex p1 = lsolve(diff(L.w, ex_to<symbol>(PHI())) == beta, ex_to<symbol>(PHI()));
    ex w1v = expand(L.w.subs(PHI() == p1));
    // Eq. 8 on the right piece: a quadratic in phi2; its roots are (1 +- sqrt 2)(8 - beta)/32 (Vieta)
    ex q = expand(Rr.w - w1v - beta * (PHI() - p1));
    ex r1 = (1 + sqrt(ex(2))) * (8 - beta) / 32, r2 = (1 - sqrt(ex(2))) * (8 - beta) / 32;
    ex qa = q.coeff(PHI(), 2), qb = q.coeff(PHI(), 1), qc = q.coeff(PHI(), 0);
    ck.zero(expand(r1 + r2 + qb / qa) + expand(r1 * r2 - qc / qa),
            "quad: Eq. 8 on the right piece has the roots (1 +- sqrt2)(8 - beta)/32 (sum and product)");
    ck.zero(expand(q.subs(PHI() == r1)), "quad: phi2 = (1 + sqrt2)(8 - beta)/32 solves Eq. 8");
    ex p2 = r1;
    // w - ramp >= 0 on the stick: 16 (phi - phi1)^2 on the left piece (tangent ramp, Eq. 4), and
    // 16 (q^2 + 2 q phi - phi^2), q = (8 - beta)/32, on the right piece (positive between 0 and phi2)
    ex ramp = w1v + beta * (PHI() - p1), qq = (8 - beta) / 32;
    ck.zero(expand(L.w - ramp - 16 * pow(PHI() - p1, 2)), "quad: w - ramp = 16 (phi - phi1)^2 on [phi1, 0] (ramp tangent at phi1)");
    ck.zero(expand(Rr.w - ramp - 16 * (qq * qq + 2 * qq * PHI() - pow(PHI(), 2))),
            "quad: w - ramp = 16 (q^2 + 2 q phi - phi^2), q = (8 - beta)/32, on [0, phi2]: roots (1 +- sqrt2) q");
    // regime 24 - 16 sqrt2 < beta < 8: phi1 in (-1/4, 0), phi2 in (0, 1/2); checked at sampled rationals
    bool inside = true;
    for (int k = 1; k <= 40; ++k) {
      ex bv = ex(24 - 16 * sqrt(ex(2))) + (8 - (24 - 16 * sqrt(ex(2)))) * numeric(k, 41);
      ex c[] = {p1 + numeric(1, 4), -p1, p2, numeric(1, 2) - p2};
      for (auto& ci : c) {
        ex v = evalf(ci.subs(beta == bv));
        inside = inside && is_a<numeric>(v) && ex_to<numeric>(v).is_positive();
      }
    }
    ck.ok(inside, "quad: -1/4 < phi1 < 0 < phi2 < 1/2 at 40 points of 24 - 16 sqrt2 < beta < 8 (numeric)");
    ck.zero(expand((p2 - numeric(1, 2)).subs(beta == 24 - 16 * sqrt(ex(2)))), "quad: phi2 = 1/2 exactly at beta = 24 - 16 sqrt2 (the regime's edge)");
    std::vector<StickPhase> st = {{p1, p2, w1v}};
    std::vector<Interval> iv = {{L, numeric(-1, 2), p1, -1}, {L, p1, 0, 0}, {Rr, 0, p2, 0}, {Rr, p2, numeric(1, 2), -1}};
    Explicit r = explicit_wave(iv, st, to_beta, Fz_t);
    r.Psi_general = expand(r.Psi_general);
    r.dFx = expand(r.dFx);
    std::cout << "-- quad (C^1, piecewise quadratic), 24 - 16 sqrt2 < beta < 8, ubar > A\n"
              << "     stick from phi1 = " << p1 << " (w' = beta) to phi2 = " << p2 << "\n"
              << "     Psi = " << r.Psi_general << "\n";
    ck.zero(r.FzMean - kz * ub, "quad: <F_z> = k_z ubar by direct integration (zero mean)");
    ck.zero(expand(r.dFx - mu0 * kz * A * r.Psi_general), "quad: Delta F_x (Eq. 10, integrated in t) = mu0 k_z A Psi (Eq. 12 with the explicit w1, I)");
    ck.zero(diff(r.dFx, s.ub), "quad: Delta F_x does not depend on ubar");
    ck.zero(expand(numer(normal(r.FxMean / r.FzMean - mu0 * (1 - alpha * r.Psi_general)))),
            "quad: <F_x>/<F_z> = mu0 (1 - alpha Psi) (Eq. 13)");
    ck.zero(expand(r.Psi_general - (3 + 2 * sqrt(ex(2))) * pow(8 - beta, 3) / 3072),
            "quad: Psi = (3 + 2 sqrt2)(8 - beta)^3/3072 = (1 + sqrt2)^2 (8 - beta)^3/3072 on this branch");
    ck.nonzero(expand(r.Psi_general - pow(8 - beta, 3) / 1024), "quad: Psi = (8 - beta)^3/1024 (sqrt2 part dropped)");
  }

  // ------------------------------------------------------------------ 4. control: clipped triangle
  // -1 < gamma = ubar/A < 1: F_z = k_z max(ubar + A w, 0). Eq. 11 still holds for the stick phase
  // (it lies inside the contact), but <F_z> = k_z ubar fails, and with it Eq. 13.
  {
    std::cout << "== control: clipped triangle, -1 < gamma = ubar/A < 1, 0 < beta < 4\n";
    Regime R = make_regime("0 < beta < 4, -1 < gamma < 1", {{0, -1}, {0, 1}, {4, 1}, {4, -1}});
    const exmap ubg = {{s.ub, g * A}};
    Piece up{0, numeric(1, 2), 4 * PHI() - 1}, dn{numeric(1, 2), 1, 3 - 4 * PHI()};
    ex pc = (1 - g) / 4, pe = (3 + g) / 4;  // contact: gamma + w > 0 on (pc, pe)
    ck.zero(Fz_t.subs(W == up.w.subs(PHI() == pc)).subs(ubg), "clipped tri: F_z = 0 at first contact pc = (1 - gamma)/4");
    // stick from first contact (slope 4 > beta; in the air F_x = 0 = mu0 F_z, i.e. slip just before)
    ex w1v = -g;  // w(pc)
    symbol tt("tt");
    ex p2 = normal((f * lsolve(mu0 * Fz_t.subs(W == w1v) + kx * v0 * (tt - pc / f) ==
                                   mu0 * Fz_t.subs(W == dn.w.subs(PHI() == f * tt)), tt)).subs(to_beta).subs(ubg));
    ck.ok(decide(p2 - numeric(1, 2), R, "clipped tri phi2 - 1/2") > 0 && decide(pe - p2, R, "clipped tri pe - phi2") > 0,
          "clipped tri: the stick end " + ex_to_string(p2) + " lies on the falling flank, inside the contact (proved sign)");
    std::vector<StickPhase> st = {{pc, p2, w1v}};
    std::vector<Interval> iv = {{up, pc, numeric(1, 2), 0}, {dn, numeric(1, 2), p2, 0}, {dn, p2, pe, -1}};  // air: F = 0
    Explicit r = explicit_wave(iv, st, to_beta, Fz_t.subs(ubg));
    ex mu_true = normal(r.FxMean / r.FzMean);
    ex Psi_c = r.Psi_general;
    std::cout << "     <F_z> = " << factor(r.FzMean) << ",  Psi (Eq. 12 over the stick) = " << factor(Psi_c)
              << ",  true mu/mu0 = " << normal(mu_true / mu0) << "\n";
    ck.zero(r.dFx - mu0 * kz * A * Psi_c, "clipped tri: Eq. 11 still holds (the stick lies inside the contact)");
    ck.nonzero(r.FzMean - kz * g * A, "clipped tri: <F_z> = k_z ubar");
    ck.zero(r.FzMean - kz * A * pow(1 + g, 2) / 4, "clipped tri: <F_z> = k_z A (1 + gamma)^2/4");
    ck.zero(mu_true / mu0 - 2 * beta / (4 + beta), "clipped tri: true mu/mu0 = 2 beta/(4 + beta) (Eq. 19)");
    Result e = run(clip(wave("tri"), g, R), beta, R);
    ck.zero(mu_true / mu0 - e.mu, "clipped tri: true mu/mu0 = engine mu");
    ck.nonzero(mu_true - mu0 * (1 - Psi_c / g), "clipped tri: Eq. 13, mu0 (1 - alpha Psi) with this Psi");
    ck.nonzero(mu_true - mu0 * (1 - (4 - beta) / (4 + beta) / g), "clipped tri: Eq. 13 with the unclipped Psi_tri (Eq. 17)");
    ck.nonzero(diff(Psi_c, G()), "clipped tri: Psi independent of ubar (it depends on gamma here)");
  }
  print_conditions();
  return ck.finish("proof.eqs7_13_reduction");
}
