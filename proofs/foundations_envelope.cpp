// Foundations of model.md: the steady state and the envelope s(phi) = min_{0<=tau<1} [n(phi-tau) + beta tau].
// Proved in foundations_envelope.md: from an admissible start (phi0, s0), s0 <= n(phi0), the dynamics gives
//   s(phi) = min( s0 + beta (phi - phi0), inf_{phi0 < t <= phi} [n(t) + beta (phi - t)] )      (R)
// hence s = min(s0 + beta(phi - phi0), E(phi)) for phi >= phi0 + 1, s = E from phi0 + k on with
// k = max(1, ceil((E(phi0) - s0)/beta)), and E is the unique periodic solution. model.md's "one period from
// any admissible start" is false (far-below starts need k periods).
// Checked here against an independent event-stepping integration of the rules of model.md:
//  * piecewise-linear waves (tri, str, stl, sqr and random waves with jumps and several minima) in EXACT
//    rational arithmetic (GiNaC numeric): function equality on whole periods (all kinks and jumps are
//    enumerated, so agreement at the check points proves equality of the piecewise-linear functions);
//  * the sine at 120 digits (mpfr), event stepping with a bracketed bisection root finder.
#include "engine.hpp"

#include <boost/multiprecision/mpfr.hpp>

#include <algorithm>
#include <iomanip>
#include <set>

using namespace proofs;

namespace {

// ======================================================================= exact, piecewise linear
numeric floor_q(const numeric& q) { return (q.numer() - mod(q.numer(), q.denom())) / q.denom(); }
numeric ceil_q(const numeric& q) { return -floor_q(-q); }
numeric qmin(const numeric& a, const numeric& b) { return a < b ? a : b; }

struct Piece { numeric x0, x1, a, m; };  // n = a + m (t - x0) on [x0, x1) in [0, 1); right-continuous

struct PL {
  std::string name;
  std::vector<Piece> P;
  size_t find(const numeric& f) const {  // piece with x0 <= f < x1, f in [0, 1)
    for (size_t i = 0; i < P.size(); ++i) if (P[i].x0 <= f && f < P[i].x1) return i;
    throw std::runtime_error("phase outside [0,1)");
  }
  numeric at(const numeric& t) const {  // right value
    numeric b = floor_q(t), f = t - b;
    const Piece& p = P[find(f)];
    return p.a + p.m * (f - p.x0);
  }
  numeric left(const numeric& t) const {  // left limit
    numeric b = floor_q(t), f = t - b;
    if (f.is_zero()) { f = 1; }
    for (auto& p : P) if (p.x0 < f && f <= p.x1) return p.a + p.m * (f - p.x0);
    throw std::runtime_error("left limit");
  }
  numeric lo_star(const numeric& t) const { return qmin(at(t), left(t)); }
  // breakpoint copies x with lo <= x <= hi (closed)
  std::vector<numeric> breaks(const numeric& lo, const numeric& hi) const {
    std::vector<numeric> out;
    for (numeric k = floor_q(lo) - 1; k <= floor_q(hi) + 1; k += 1)
      for (auto& p : P) { numeric x = k + p.x0; if (lo <= x && x <= hi) out.push_back(x); }
    std::sort(out.begin(), out.end(), [](const numeric& a, const numeric& b) { return a < b; });
    return out;
  }
};

PL from_engine(const std::string& w) {
  PL r{w, {}};
  for (auto& s : wave(w))
    r.P.push_back({ex_to<numeric>(s.x0), ex_to<numeric>(s.x1), ex_to<numeric>(s.a), ex_to<numeric>(s.m)});
  return r;
}

// n = max(gamma + w, 0), exact clipping (contact points solve linear equations)
PL clip(const PL& w, const numeric& g) {
  PL n{w.name, {}};
  for (auto& p : w.P) {
    numeric v0 = g + p.a, v1 = g + p.a + p.m * (p.x1 - p.x0);
    if (v0 >= 0 && v1 >= 0) { n.P.push_back({p.x0, p.x1, v0, p.m}); continue; }
    if (v0 <= 0 && v1 <= 0) { n.P.push_back({p.x0, p.x1, 0, 0}); continue; }
    numeric xc = p.x0 - v0 / p.m;
    if (v0 > 0) { n.P.push_back({p.x0, xc, v0, p.m}); n.P.push_back({xc, p.x1, 0, 0}); }
    else        { n.P.push_back({p.x0, xc, 0, 0});   n.P.push_back({xc, p.x1, 0, p.m}); }
  }
  return n;
}

// random piecewise-linear wave: K pieces on a grid of 1/60, values in [-1, 1] on a grid of 1/6,
// jumps at about half of the breakpoints, alternating slopes (several local minima)
PL random_wave(unsigned seed, int K) {
  unsigned long long st = seed * 2654435761ULL + 17;
  auto rnd = [&](int lo, int hi) {
    st = st * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + int((st >> 33) % (unsigned long long)(hi - lo + 1));
  };
  std::set<int> cuts;
  while ((int)cuts.size() < K - 1) cuts.insert(rnd(2, 58));
  std::vector<numeric> xs{0};
  for (int c : cuts) xs.push_back(numeric(c, 60));
  xs.push_back(1);
  PL w{"rand" + std::to_string(seed), {}};
  numeric prev_end = numeric(rnd(-6, 6), 6);
  for (int i = 0; i < K; ++i) {
    numeric a = (rnd(0, 1) == 0) ? prev_end : numeric(rnd(-6, 6), 6);  // jump or continuous
    numeric e = numeric(rnd(-6, 6), 6);
    if (i % 2 == 0 && e > a) std::swap(a, e);  // falling then rising: local minima inside the period
    w.P.push_back({xs[i], xs[i + 1], a, (e - a) / (xs[i + 1] - xs[i])});
    prev_end = e;
  }
  return w;
}

// ---- the event dynamics of model.md, stepped exactly
struct Node { numeric t, s, slope; };  // s(t') = s + slope (t' - t) until the next node
struct Traj {
  std::vector<Node> nodes;
  numeric at(const numeric& t) const {
    auto it = std::upper_bound(nodes.begin(), nodes.end(), t, [](const numeric& x, const Node& n) { return x < n.t; });
    if (it == nodes.begin()) throw std::runtime_error("before start");
    --it;
    return it->s + it->slope * (t - it->t);
  }
};

// rules: s <= n; s' = beta while s < n (stick); where s = n, s follows n if n' <= beta (slip),
// otherwise s falls below n (stick onset, Eq. 4 / first contact); the stick ends where n meets
// the ramp (Eq. 8); at a jump of n, s(t) = min(s(t-), n(t)) (upward jump: stick onset).
Traj simulate(const PL& n, const numeric& beta, const numeric& phi0, const numeric& s0, const numeric& phi_end) {
  if (s0 > n.at(phi0)) throw std::runtime_error("inadmissible start");
  Traj tr;
  numeric phi = phi0, s = s0;
  while (phi < phi_end) {
    numeric b = floor_q(phi);
    const Piece& p = n.P[n.find(phi - b)];
    numeric X0 = b + p.x0, X1 = b + p.x1, m = p.m, nphi = p.a + m * (phi - X0), s_end;
    if (s == nphi && m <= beta) {  // slip
      tr.nodes.push_back({phi, s, m});
      s_end = p.a + m * (X1 - X0);
    } else {  // stick
      tr.nodes.push_back({phi, s, beta});
      if (s < nphi && m < beta) {
        numeric tc = phi + (nphi - s) / (beta - m);
        if (tc < X1) { s = nphi + m * (tc - phi); phi = tc; continue; }
      }
      s_end = s + beta * (X1 - phi);
    }
    phi = X1;
    s = qmin(s_end, n.at(X1));
  }
  return tr;
}

// inf over t in (lo, phi] of n(t) + slope (phi - t): candidates are t = phi (value and left limit),
// the breakpoints inside (both one-sided values) and the limit t -> lo+ (n is linear between breakpoints)
numeric inf_ramp(const PL& n, const numeric& slope, const numeric& lo, const numeric& phi) {
  numeric best = qmin(n.at(phi), n.left(phi));
  best = qmin(best, n.at(lo) + slope * (phi - lo));
  for (auto& x : n.breaks(lo, phi))
    if (lo < x && x < phi) best = qmin(best, n.lo_star(x) + slope * (phi - x));
  return best;
}

struct Case {
  const PL* n;
  numeric beta, phi0, s0;
  numeric E(const numeric& t) const { return inf_ramp(*n, beta, t - 1, t); }
  numeric R(const numeric& t) const {  // the representation (R)
    if (t == phi0) return s0;
    return qmin(s0 + beta * (t - phi0), inf_ramp(*n, beta, phi0, t));
  }
};

// Check points on [A, B]: nodes of the trajectory, breakpoints of n, and in every piece of n the
// crossing of n with the one ramp that can be active there for E and for R (the minimum over the
// sources in the window is the same line throughout the open piece). Between consecutive check
// points s, E and R are all linear, so agreement at the points and at two interior points of every
// gap proves equality on [A, B].
std::vector<numeric> check_points(const Case& c, const Traj& tr, const numeric& A, const numeric& B) {
  std::vector<numeric> pts{A, B};
  for (auto& nd : tr.nodes) if (A <= nd.t && nd.t <= B) pts.push_back(nd.t);
  auto br = c.n->breaks(A - 1, B + 1);
  for (auto& x : br) if (A <= x && x <= B) pts.push_back(x);
  for (size_t i = 0; i + 1 < br.size(); ++i) {
    numeric X0 = br[i], X1 = br[i + 1];
    if (X1 <= A || X0 >= B || X0 == X1) continue;
    numeric mid = (X0 + X1) / 2, b = floor_q(mid);
    const Piece& p = c.n->P[c.n->find(mid - b)];
    if (p.m == c.beta) continue;
    // E: sources x in [X1 - 1, X0]; R: s0 at phi0 and sources in (phi0, X0]
    numeric cE = 1000000, cR = c.s0 - c.beta * c.phi0;
    for (auto& x : c.n->breaks(X1 - 1, X0)) cE = qmin(cE, c.n->lo_star(x) - c.beta * x);
    if (X0 > c.phi0)
      for (auto& x : c.n->breaks(c.phi0, X0)) if (x > c.phi0) cR = qmin(cR, c.n->lo_star(x) - c.beta * x);
    for (auto& cc : {cE, cR}) {
      // a + m (t - (b + x0)) = cc + beta t
      numeric t = (p.a - p.m * (b + p.x0) - cc) / (c.beta - p.m);
      if (X0 < t && t < X1 && A < t && t < B) pts.push_back(t);
    }
  }
  std::sort(pts.begin(), pts.end(), [](const numeric& a, const numeric& b) { return a < b; });
  std::vector<numeric> out;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (i > 0 && pts[i] == pts[i - 1]) continue;
    if (!out.empty()) {
      numeric l = out.back(), r = pts[i];
      out.push_back(l + (r - l) / 3);
      out.push_back(l + 2 * (r - l) / 3);
    }
    out.push_back(pts[i]);
  }
  return out;
}

// first check point in [A, B] where s differs from F, or none
template <class F>
bool equal_on(const Case& c, const Traj& tr, const numeric& A, const numeric& B, F f, numeric* witness = nullptr) {
  for (auto& t : check_points(c, tr, A, B)) {
    if (t == B) continue;  // half-open [A, B)
    if (!(tr.at(t) == f(t))) { if (witness) *witness = t; return false; }
  }
  return true;
}

// ======================================================================= sine, 120 digits
namespace bmp = boost::multiprecision;
using mp = bmp::number<bmp::mpfr_float_backend<120>, bmp::et_off>;

std::string fmt(const mp& x, int d = 6) {
  std::ostringstream os;
  os << std::scientific << std::setprecision(d) << x;
  return os.str();
}

struct Sine {
  mp beta, gamma, twopi;
  std::vector<std::pair<mp, int>> ext;  // local extrema of h = n - beta t in [0, 1): (phase, -1 min / +1 max)
  Sine(const mp& b, const mp& g) : beta(b), gamma(g), twopi(2 * acos(mp(-1))) {
    auto in_contact = [&](const mp& t) { return gamma + sin(twopi * t) > 0; };
    auto fr = [](mp t) { return t - floor(t); };
    if (beta < twopi) {
      mp c = acos(beta / twopi) / twopi;
      if (in_contact(-c)) ext.push_back({fr(-c), -1});  // n' = beta, n'' > 0 (Eq. 4)
      if (in_contact(c)) ext.push_back({fr(c), +1});
    }
    if (gamma > -1 && gamma < 1) {
      mp ton = asin(-gamma) / twopi;  // first contact, a local minimum of h if n'(ton+) > beta
      if (twopi * sqrt(1 - gamma * gamma) > beta) ext.push_back({fr(ton), -1});
    }
    std::sort(ext.begin(), ext.end());
    // a max must separate two minima; if the contact entry and Eq. 4 both qualified, keep the proper one
    for (size_t i = 0; i + 1 < ext.size(); ++i)
      if (ext[i].second == ext[i + 1].second) throw std::runtime_error("extrema do not alternate");
  }
  mp n(const mp& t) const { mp v = gamma + sin(twopi * t); return v > 0 ? v : mp(0); }
  mp dn(const mp& t) const { return gamma + sin(twopi * t) > 0 ? mp(twopi * cos(twopi * t)) : mp(0); }
  mp h(const mp& t) const { return n(t) - beta * t; }
  // extrema copies in (lo, hi]
  std::vector<std::pair<mp, int>> ext_in(const mp& lo, const mp& hi) const {
    std::vector<std::pair<mp, int>> out;
    for (long k = (long)floor(lo).convert_to<double>() - 1; k <= (long)floor(hi).convert_to<double>() + 1; ++k)
      for (auto& e : ext) { mp x = e.first + k; if (lo < x && x <= hi) out.push_back({x, e.second}); }
    std::sort(out.begin(), out.end());
    return out;
  }
  mp inf_ramp(const mp& lo, const mp& phi, const mp* s0 = nullptr) const {  // sources: local minima of h
    mp best = n(phi);
    if (s0) best = std::min(best, *s0 + beta * (phi - lo));
    for (auto& e : ext_in(lo, phi)) if (e.second < 0 && e.first < phi) best = std::min(best, n(e.first) + beta * (phi - e.first));
    return best;
  }
  mp E(const mp& t) const { return inf_ramp(t - 1, t); }
};

struct Seg { mp a, b; bool stick; mp sa; };  // on [a, b): stick: s = sa + beta (t - a); slip: s = n
struct STraj {
  std::vector<Seg> segs;
  mp at(const Sine& w, const mp& t) const {
    for (auto& g : segs) if (g.a <= t && t < g.b) return g.stick ? mp(g.sa + w.beta * (t - g.a)) : w.n(t);
    throw std::runtime_error("outside trajectory");
  }
};

STraj simulate_sine(const Sine& w, const mp& phi0, const mp& s0, const mp& phi_end) {
  STraj tr;
  mp phi = phi0, s = s0;
  bool stick = s < w.n(phi) || w.dn(phi) > w.beta;
  while (phi < phi_end) {
    if (stick) {
      const mp c = s - w.beta * phi;  // ramp: h(t) = c at its end
      mp prev = phi, te = -1;
      for (int guard = 0; guard < 100000 && te < 0; ++guard) {
        // next check point: the next extremum, or (no extrema) the next integer shift
        auto xs = w.ext_in(prev, prev + 1);
        mp q = xs.empty() ? mp(prev + 1) : xs.front().first;
        if (w.h(q) - c <= 0) {  // h decreases monotonically from > c to <= c on (prev, q]
          mp lo = prev, hi = q;
          for (int i = 0; i < 420; ++i) { mp m = (lo + hi) / 2; (w.h(m) - c > 0 ? lo : hi) = m; }
          te = hi;
        }
        prev = q;
      }
      if (te < 0) throw std::runtime_error("stick end not found");
      tr.segs.push_back({phi, te, true, s});
      phi = te; s = w.n(te); stick = false;
    } else {  // slip until the next local minimum of h
      auto xs = w.ext_in(phi, phi + 1);
      mp q = phi_end + 2;
      for (auto& e : xs) if (e.second < 0 && e.first > phi) { q = e.first; break; }
      tr.segs.push_back({phi, q, false, 0});
      phi = q; s = w.n(q); stick = true;
    }
  }
  return tr;
}

}  // namespace

int main() {
  Checker ck;
  auto silent = [&](bool c, const std::string& what) { if (c) ++ck.passes; else ck.ok(false, what); };

  // ------------------------------------------------------------------ exact, piecewise linear
  std::cout << "=== Piecewise-linear waves, exact rational arithmetic ===\n";
  std::vector<PL> waves;
  for (auto w : {"tri", "str", "stl", "sqr"}) waves.push_back(from_engine(w));
  for (unsigned seed : {1u, 2u, 3u}) waves.push_back(random_wave(seed, 7 + seed % 3));
  for (auto& w : waves) {
    if (w.name.rfind("rand", 0) != 0) continue;
    std::cout << "  " << w.name << ": ";
    for (auto& p : w.P) std::cout << "[" << p.x0 << "," << p.x1 << "): " << p.a << (p.m < 0 ? "" : "+") << p.m << "(t-" << p.x0 << ")  ";
    // local minima of w (lower semicontinuous version): value at x below both one-sided neighbourhoods
    int minima = 0;
    for (size_t i = 0; i < w.P.size(); ++i) {
      const Piece& l = w.P[(i + w.P.size() - 1) % w.P.size()];
      const Piece& r = w.P[i];
      numeric L = l.a + l.m * (l.x1 - l.x0), R = r.a, lo = qmin(L, R);
      bool from_left = l.m < 0 || L > lo, to_right = r.m > 0 || R > lo;
      if (from_left && to_right) ++minima;
    }
    int jumps = 0;
    for (size_t i = 0; i < w.P.size(); ++i) {
      const Piece& l = w.P[(i + w.P.size() - 1) % w.P.size()];
      if (!(l.a + l.m * (l.x1 - l.x0) == w.P[i].a)) ++jumps;
    }
    std::cout << "\n     " << jumps << " jumps, " << minima << " local minima per period\n";
    ck.ok(jumps >= 2 && minima >= 2, w.name + ": random wave with jumps and several minima");
  }
  const std::vector<numeric> gammas = {3, 1, numeric(1, 2), 0, numeric(-1, 2)};
  const std::vector<numeric> betas = {numeric(1, 10), 1, 5};
  int n_runs = 0, n_rep = 0, n_env = 0, n_late = 0, n_far = 0, n_map = 0, n_neg = 0, n_half = 0, n_half_tried = 0, n_fix = 0;
  for (auto& w : waves)
    for (auto& g : gammas) {
      PL n = clip(w, g);
      numeric nmax = 0;
      for (auto& p : n.P) nmax = -qmin(-nmax, qmin(-p.a, -(p.a + p.m * (p.x1 - p.x0))));
      if (nmax <= 0) continue;  // no contact
      for (auto& be : betas) {
        numeric phi0 = numeric(37, 100);
        Case base{&n, be, phi0, 0};
        numeric E0 = base.E(phi0), n0 = n.at(phi0);
        struct Start { std::string what; numeric s0; };
        std::vector<Start> starts = {{"slip (s0 = n)", n0}, {"fixed point (s0 = E)", E0},
                                     {"below E by 2beta/3", E0 - 2 * be / 3}, {"below E by exactly beta", E0 - be},
                                     {"below E by beta(1 + 1/97)", E0 - be - be / 97}, {"far below, E - 9beta/2", E0 - 9 * be / 2}};
        if (E0 < n0) starts.push_back({"between E and n", (E0 + n0) / 2});
        for (auto& st : starts) {
          ++n_runs;
          Case c{&n, be, phi0, st.s0};
          numeric k = numeric(1);
          if (E0 - st.s0 > be) k = ceil_q((E0 - st.s0) / be);  // predicted number of periods
          std::string tag = n.name + " gamma=" + ex_to_string(g) + " beta=" + ex_to_string(be) + " start " + st.what + " (k=" + ex_to_string(k) + ")";
          Traj tr = simulate(n, be, phi0, st.s0, phi0 + k + 2);
          // (R) on [phi0, phi0 + k + 1]
          bool rep = equal_on(c, tr, phi0, phi0 + k + 1, [&](const numeric& t) { return c.R(t); });
          silent(rep, "representation (R) holds exactly on [phi0, phi0+k+1]: " + tag);
          n_rep += rep;
          // s = E on [phi0 + k, phi0 + k + 1]
          bool env = equal_on(c, tr, phi0 + k, phi0 + k + 1, [&](const numeric& t) { return c.E(t); });
          silent(env, "s = E exactly on [phi0+k, phi0+k+1): " + tag);
          n_env += env;
          if (st.what.rfind("fixed", 0) == 0) {
            bool fx = equal_on(c, tr, phi0, phi0 + 1, [&](const numeric& t) { return c.E(t); });
            silent(fx, "E itself is a trajectory (s0 = E(phi0) gives s = E from the start): " + tag);
            n_fix += fx;
          }
          // not yet on the envelope one period earlier (k > 1): the period count is sharp
          if (k > 1) {
            numeric t = phi0 + k - 1;
            bool late = tr.at(t) < c.E(t);
            silent(late, "s < E at phi0 + k - 1 (k is sharp): " + tag);
            n_late += late;
            numeric wit;
            bool one = equal_on(c, tr, phi0 + 1, phi0 + 2, [&](const numeric& t) { return c.E(t); }, &wit);
            silent(!one, "model.md 'one period from any start' fails: " + tag);
            n_far += !one;
          }
          // Poincare map P(s0) = s(phi0 + 1) = min(s0 + beta, E(phi0)); fixed point only at s0 = E(phi0)
          numeric P = tr.at(phi0 + 1);
          bool map = (P == qmin(st.s0 + be, E0)) && ((P == st.s0) == (st.s0 == E0));
          silent(map, "Poincare map P(s0) = min(s0 + beta, E(phi0)), fixed iff s0 = E(phi0): " + tag);
          n_map += map;
          // wrong variants on the steady state: ramp slope -beta, window of half a period
          numeric A = phi0 + k;
          bool neg = !equal_on(c, tr, A, A + 1, [&](const numeric& t) { return inf_ramp(n, -be, t - 1, t); });
          silent(neg, "wrong variant rejected (envelope with slope -beta): " + tag);
          n_neg += neg;
          ++n_half_tried;
          n_half += !equal_on(c, tr, A, A + 1, [&](const numeric& t) { return inf_ramp(n, be, t - numeric(1, 2), t); });
        }
      }
    }
  std::cout << "  " << n_runs << " runs (7 waves x gamma in {3, 1, 1/2, 0, -1/2} x beta in {1/10, 1, 5} x up to 7 starts)\n";
  ck.ok(n_rep == n_runs, "representation (R) = event dynamics, exactly, on [phi0, phi0 + k + 1]: " + std::to_string(n_rep) + "/" + std::to_string(n_runs));
  ck.ok(n_env == n_runs, "s = E exactly from phi0 + k on, k = max(1, ceil((E(phi0) - s0)/beta)): " + std::to_string(n_env) + "/" + std::to_string(n_runs));
  ck.ok(n_fix > 0 && n_late > 0, "s0 = E(phi0): s = E from the start (" + std::to_string(n_fix) + " runs); k sharp for every k > 1 run (" +
                                     std::to_string(n_late) + " runs: s < E at phi0 + k - 1)");
  ck.ok(n_map == n_runs, "Poincare map min(s0 + beta, E(phi0)), unique fixed point s0 = E(phi0): " + std::to_string(n_map) + "/" + std::to_string(n_runs));
  ck.ok(n_far == n_late && n_far > 0, "wrong variant rejected: model.md's 'one period from any admissible start' fails in all " + std::to_string(n_far) + " runs with k > 1");
  ck.ok(n_neg == n_runs, "wrong variant rejected: envelope with ramp slope -beta differs from the steady state in " + std::to_string(n_neg) + "/" + std::to_string(n_runs) + " runs");
  ck.ok(n_half > 0, "wrong variant rejected: window of half a period differs from the steady state in " + std::to_string(n_half) + "/" +
                        std::to_string(n_half_tried) + " runs (where ramps span more than half a period)");

  // the counterexample: triangle, gamma = 3, beta = 1/10, s0 = 0 at the minimum phi0 = 0
  {
    std::cout << "-- counterexample to 'one period from any admissible start': triangle, gamma = 3, beta = 1/10, s0 = 0 at phi0 = 0\n";
    PL n = clip(from_engine("tri"), 3);
    numeric be(1, 10), phi0 = 0, s0 = 0;
    Case c{&n, be, phi0, s0};
    numeric E0 = c.E(phi0), k = ceil_q((E0 - s0) / be);
    std::cout << "     E(phi0) = " << E0 << ", n(phi0) = " << n.at(phi0) << ", predicted k = ceil((E - s0)/beta) = " << k << "\n";
    Traj tr = simulate(n, be, phi0, s0, phi0 + k + 2);
    ck.ok(equal_on(c, tr, phi0, phi0 + k + 1, [&](const numeric& t) { return c.R(t); }), "representation (R) exact on all " + ex_to_string(k + 1) + " periods");
    for (int j = 1; j <= k.to_int(); ++j) {
      bool eq = equal_on(c, tr, phi0 + j, phi0 + j + 1, [&](const numeric& t) { return c.E(t); });
      if (j == 1 || j >= k.to_int() - 1)
        std::cout << "     period " << j << ": s(phi0 + " << j << ") = " << tr.at(phi0 + j) << ", E = " << c.E(phi0 + j)
                  << (eq ? ",  s = E on the whole period" : ",  s != E") << "\n";
      silent(eq == (j >= k.to_int()), "period " + std::to_string(j));
    }
    ck.ok(!equal_on(c, tr, phi0 + 1, phi0 + 2, [&](const numeric& t) { return c.E(t); }),
          "wrong variant rejected: model.md's 'one period' (s != E on [1, 2))");
    ck.ok(!equal_on(c, tr, phi0 + k - 1, phi0 + k, [&](const numeric& t) { return c.E(t); }) &&
              equal_on(c, tr, phi0 + k, phi0 + k + 1, [&](const numeric& t) { return c.E(t); }),
          "s = E from exactly k = " + ex_to_string(k) + " periods on, not from k - 1");
    // half-window envelope is wrong here: the ramp from the minimum spans more than half a period
    Traj st = simulate(n, be, phi0, E0, phi0 + 2);
    ck.ok(!equal_on(c, st, phi0 + 1, phi0 + 2, [&](const numeric& t) { return inf_ramp(n, be, t - numeric(1, 2), t); }),
          "wrong variant rejected: envelope over a window of half a period (tri, gamma = 3, beta = 1/10)");
  }

  // ------------------------------------------------------------------ sine, 120 digits
  std::cout << "=== Sine, 120-digit event stepping (bisection root finder), tolerance 1e-95 ===\n";
  const mp tol("1e-95");
  mp worst_env = 0, worst_rep = 0;
  int s_runs = 0;
  for (const char* gs : {"3", "1", "0.5", "0", "-0.5"})
    for (const char* bs : {"0.1", "1", "3", "7"}) {
      Sine w{mp(bs), mp(gs)};
      {  // the extrema list is complete: h' = n' - beta keeps its sign between listed extrema (grid of 4000)
        bool ok = true;
        for (int i = 0; i < 4000; ++i) {
          mp t = (mp(i) + mp("0.5")) / 4000;
          auto xs = w.ext_in(t - 1, t);  // last extremum at or before t
          if (xs.empty()) { ok = ok && (w.dn(t) - w.beta <= 0); continue; }
          int type = xs.back().second;   // after a min h increases, after a max it decreases
          mp d = w.dn(t) - w.beta;
          ok = ok && (type < 0 ? d >= 0 : d <= 0);
        }
        silent(ok, std::string("sine extrema list complete: gamma=") + gs + " beta=" + bs);
      }
      mp phi0("0.37"), E0 = w.E(phi0), n0 = w.n(phi0);
      struct St { const char* what; mp s0; int k; };
      std::vector<St> sts = {{"slip", n0, 1}, {"below E by beta/2", E0 - w.beta / 2, 1}, {"far below, E - 9beta/2", E0 - 9 * w.beta / 2, 5}};
      for (auto& st : sts) {
        ++s_runs;
        STraj tr = simulate_sine(w, phi0, st.s0, phi0 + st.k + 2);
        std::string tag = std::string("sine gamma=") + gs + " beta=" + bs + " start " + st.what;
        mp de = 0, dr = 0;
        for (int i = 0; i < 64; ++i) {
          mp t = phi0 + st.k + mp(i) / 64 + mp("0.001");
          de = std::max(de, abs(tr.at(w, t) - w.E(t)));
          for (int j = 0; j <= st.k; ++j) {
            mp tj = phi0 + j + mp(i) / 64 + mp("0.001");
            dr = std::max(dr, abs(tr.at(w, tj) - w.inf_ramp(phi0, tj, &st.s0)));
          }
        }
        worst_env = std::max(worst_env, de);
        worst_rep = std::max(worst_rep, dr);
        silent(de < tol, "sine: s = E on period k: " + tag + " max diff " + fmt(de));
        silent(dr < tol, "sine: representation (R): " + tag + " max diff " + fmt(dr));
        // the trajectory obeys the rules of model.md (checked on 40 points per segment, independently of
        // the extrema list): slip only where n' <= beta, stick strictly below n, the stick ends on n
        bool rules = true;
        for (auto& g : tr.segs) {
          mp b = std::min(g.b, mp(phi0 + st.k + 2));
          for (int i = 1; i < 40; ++i) {
            mp t = g.a + (b - g.a) * i / 40;
            if (g.stick) rules = rules && (g.sa + w.beta * (t - g.a) < w.n(t));
            else rules = rules && (w.dn(t) <= w.beta);
          }
          if (g.stick) rules = rules && abs(g.sa + w.beta * (g.b - g.a) - w.n(g.b)) < tol;
        }
        silent(rules, "sine: trajectory obeys the rules: " + tag);
        mp P = tr.at(w, phi0 + 1);
        silent(abs(P - std::min(mp(st.s0 + w.beta), E0)) < tol, "sine: Poincare map: " + tag);
        if (st.k > 1) {
          mp t = phi0 + st.k - 1;
          silent(E0 - tr.at(w, t) > w.beta / 4, "sine: k sharp: " + tag);
          silent(abs(tr.at(w, phi0 + 1) - w.E(phi0 + 1)) > w.beta, "sine: one period not enough: " + tag);
        }
      }
    }
  std::cout << "  " << s_runs << " runs: max |s - E| on period k = " << fmt(worst_env, 3) << ", max |s - (R)| on periods 0..k = " << fmt(worst_rep, 3) << "\n";
  ck.ok(worst_env < tol && worst_rep < tol, "sine (gamma in {3,1,0.5,0,-0.5}, beta in {0.1,1,3,7}, 3 starts): s = E from period k on, and (R), to 1e-95");
  {
    Sine w{mp("0.1"), mp(3)};
    mp phi0("0.75"), s0 = 0, E0 = w.E(phi0);
    STraj tr = simulate_sine(w, phi0, s0, phi0 + 22);
    std::cout << "-- sine, gamma = 3, beta = 0.1, s0 = 0 at the minimum phi0 = 3/4: E(phi0) = " << std::setprecision(30) << E0 << "\n";
    int first = -1;
    for (int j = 1; j <= 21; ++j) {
      mp d = 0;
      for (int i = 0; i < 32; ++i) { mp t = phi0 + j + mp(i) / 32; d = std::max(d, abs(tr.at(w, t) - w.E(t))); }
      if (d < tol && first < 0) first = j;
      if (j == 1 || j == 19 || j == 20) std::cout << "     period " << j << ": max |s - E| = " << fmt(d, 3) << "\n";
    }
    ck.ok(first == 20, "sine: s reaches E after exactly k = ceil(2/0.1) = 20 periods (first period with |s - E| < 1e-95: " + std::to_string(first) + ")");
    ck.ok(abs(tr.at(w, phi0 + 1) - w.E(phi0 + 1)) > mp("1.8"), "wrong variant rejected: model.md's 'one period' for the sine (|s - E| = 1.9 at phi0 + 1)");
  }
  return ck.finish("proof.foundations_envelope");
}
