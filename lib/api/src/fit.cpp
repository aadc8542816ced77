#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/input_value.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

constexpr int coefficient_digits = 17;
constexpr int residual_digits = 3;
// Refused above this condition number (Frobenius estimate ||R||·||R⁻¹||): data given to about 17
// digits then determine fewer than 5 digits of the coefficients.
constexpr double max_condition = 1e12;

// Working digits: 70, plus what the sums lose: log10 N and log10 of the unknowns for the
// accumulated rounding, and the digits an offset large against the amplitude cancels,
// log10(2 max|y| / (max − min)). Then every coefficient is within 1e-40·max|y| of the exact
// least-squares value (κ² · 10^-70 ≤ 10^-46 for the largest κ accepted), and one below that is
// written as 0: its digits would be rounding noise.
unsigned working_digits(const WaveSpec& wave, std::size_t unknowns) {
  PrecisionScope scope(60);
  mpfr lo = wave.samples.front().to<mpfr>(), hi = lo, big = abs(lo);
  for (const auto& t : wave.samples) {
    const mpfr v = t.to<mpfr>();
    if (v < lo) lo = v;
    if (v > hi) hi = v;
    if (abs(v) > big) big = abs(v);
  }
  int cancelled = 0;
  if (hi > lo) cancelled = std::max(0, static_cast<int>(std::ceil(static_cast<double>(log10(mpfr(2 * big / (hi - lo)))))));
  const auto digits10 = [](double x) { return static_cast<int>(std::ceil(std::log10(std::max(x, 1.0)))); };
  return static_cast<unsigned>(70 + digits10(static_cast<double>(wave.samples.size())) +
                               digits10(static_cast<double>(unknowns)) + cancelled);
}

// Householder triangularisation of the rows × (m + 1) block `a` (column m the right-hand side), in
// place: afterwards rows 0 … m−1 hold R and Qᵀb (rows below are the residual's, dropped by the caller).
void householder(std::vector<std::vector<mpfr>>& a, std::size_t m) {
  const std::size_t rows = a.size();
  for (std::size_t j = 0; j < m && j < rows; ++j) {
    mpfr norm2 = 0;
    for (std::size_t i = j; i < rows; ++i) norm2 += a[i][j] * a[i][j];
    if (norm2 == 0) continue;
    const mpfr norm = sqrt(norm2);
    const mpfr alpha = a[j][j] > 0 ? mpfr(-norm) : norm;
    std::vector<mpfr> v(rows - j);
    for (std::size_t i = j; i < rows; ++i) v[i - j] = a[i][j];
    v[0] -= alpha;
    mpfr vnorm2 = 0;
    for (const mpfr& x : v) vnorm2 += x * x;
    if (vnorm2 == 0) continue;
    for (std::size_t l = j; l <= m; ++l) {
      mpfr s = 0;
      for (std::size_t i = j; i < rows; ++i) s += v[i - j] * a[i][l];
      const mpfr f = 2 * s / vnorm2;
      for (std::size_t i = j; i < rows; ++i) a[i][l] -= f * v[i - j];
    }
    a[j][j] = alpha;
    for (std::size_t i = j + 1; i < rows; ++i) a[i][j] = 0;
  }
}

std::string kmax_text(std::size_t n) { return std::to_string(n >= 1 ? (n - 1) / 2 : 0); }

}  // namespace

FourierFit fit_fourier(const WaveSpec& wave, unsigned harmonics) {
  if (wave.kind != WaveKind::samples)
    throw InputError("fit of wave " + quoted(detail::visible(wave.name)) +
                     ": expected a samples:FILE wave (a Fourier fit needs samples)");
  if (harmonics == 0) throw InputError("harmonics K = 0 for the fit of " + quoted(detail::visible(wave.name)) + ": expected at least 1");
  if (harmonics > static_cast<unsigned>(max_fit_harmonics))
    throw InputError("harmonics K = " + std::to_string(harmonics) + " for the fit of " + quoted(detail::visible(wave.name)) +
                     ": expected at most " + std::to_string(max_fit_harmonics));
  const std::size_t n = wave.samples.size(), k_count = harmonics, m = 2 * k_count + 1;
  if (n < m)
    throw InputError("fit of " + std::to_string(harmonics) + " harmonics to " + quoted(detail::visible(wave.name)) + ": its " +
                     std::to_string(n) + " samples determine at most " + kmax_text(n) +
                     " harmonics: expected K <= " + kmax_text(n) + " (2K + 1 <= N)");
  const bool uniform = wave.times.empty();
  if (!uniform && wave.times.size() != n + 1)
    throw InputError("fit of " + quoted(detail::visible(wave.name)) + ": " + std::to_string(wave.times.size()) +
                     " time stamps for " + std::to_string(n) + " samples: expected N + 1 (with the end point)");
  const unsigned digits = working_digits(wave, m);
  PrecisionScope scope(digits);
  std::vector<mpfr> y(n), phi;
  // Averaged periods: a sample is the sum of K values, the fit is of their mean.
  for (std::size_t j = 0; j < n; ++j) y[j] = mpfr(wave.samples[j].to<mpfr>() / static_cast<long>(wave.periods_averaged));

  std::vector<mpfr> a(k_count + 1, mpfr(0)), b(k_count + 1, mpfr(0));
  std::ostringstream method;
  // cos/sin of 2πkφ_j for k = 1 … K, by the angle-addition recurrence from k = 1 (its rounding
  // grows like k ulp, far below the working precision's margin).
  std::vector<mpfr> cos_table, sin_table;  // uniform: cos, sin of 2π r/N, r = 0 … N−1
  const auto basis = [&](std::size_t j, std::vector<mpfr>& c, std::vector<mpfr>& s) {
    c.resize(k_count + 1);
    s.resize(k_count + 1);
    if (uniform) {
      for (std::size_t k = 1; k <= k_count; ++k) {
        const std::size_t r = static_cast<std::size_t>((static_cast<unsigned long long>(k) * j) % n);
        c[k] = cos_table[r];
        s[k] = sin_table[r];
      }
      return;
    }
    const mpfr theta = 2 * boost::math::constants::pi<mpfr>() * phi[j];
    const mpfr c1 = cos(theta), s1 = sin(theta);
    c[1] = c1;
    s[1] = s1;
    for (std::size_t k = 2; k <= k_count; ++k) {
      c[k] = c[k - 1] * c1 - s[k - 1] * s1;
      s[k] = s[k - 1] * c1 + c[k - 1] * s1;
    }
  };
  std::vector<mpfr> c, s;
  if (uniform) {
    // The DFT: the exact least-squares solution for 2K < N (orthogonality on the uniform grid).
    cos_table.resize(n);
    sin_table.resize(n);
    const mpfr two_pi = 2 * boost::math::constants::pi<mpfr>();
    for (std::size_t r = 0; r < n; ++r) {
      const mpfr theta = two_pi * r / n;
      cos_table[r] = cos(theta);
      sin_table[r] = sin(theta);
    }
    for (std::size_t j = 0; j < n; ++j) {
      a[0] += y[j];
      basis(j, c, s);
      for (std::size_t k = 1; k <= k_count; ++k) {
        a[k] += y[j] * c[k];
        b[k] += y[j] * s[k];
      }
    }
    a[0] /= n;
    for (std::size_t k = 1; k <= k_count; ++k) {
      a[k] = 2 * a[k] / n;
      b[k] = 2 * b[k] / n;
    }
    method << "DFT of " << n << " samples at uniform phases j/N (the exact least-squares fit), mpfr at " << digits
           << " digits";
  } else {
    // Least squares on the phases (t_j − t_0)/T: Householder QR of [1, cos 2πkφ, sin 2πkφ | y],
    // a block of rows at a time below the R of the rows before (memory O(m²), not O(N m)).
    const auto phase = detail::sample_phase(wave);
    phi.resize(n);
    for (std::size_t j = 0; j < n; ++j) phi[j] = phase(j);
    const std::size_t block = std::max<std::size_t>(m, 64);
    std::vector<std::vector<mpfr>> rows;
    for (std::size_t j0 = 0; j0 < n; j0 += block) {
      for (std::size_t j = j0; j < std::min(n, j0 + block); ++j) {
        basis(j, c, s);
        std::vector<mpfr> row(m + 1);
        row[0] = 1;
        for (std::size_t k = 1; k <= k_count; ++k) {
          row[2 * k - 1] = c[k];
          row[2 * k] = s[k];
        }
        row[m] = y[j];
        rows.push_back(std::move(row));
      }
      householder(rows, m);
      if (rows.size() > m) rows.resize(m);
    }
    // Condition: ||R||_F · ||R⁻¹||_F ≥ κ₂(R) = κ₂(A); R⁻¹ by back substitution, column by column.
    mpfr r_norm2 = 0, inv_norm2 = 0;
    bool singular = false;
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t l = i; l < m; ++l) r_norm2 += rows[i][l] * rows[i][l];
      singular = singular || rows[i][i] == 0;
    }
    if (!singular) {
      for (std::size_t col = 0; col < m; ++col) {
        std::vector<mpfr> z(m, mpfr(0));
        for (std::size_t ii = col + 1; ii-- > 0;) {
          mpfr t = ii == col ? mpfr(1) : mpfr(0);
          for (std::size_t l = ii + 1; l <= col; ++l) t -= rows[ii][l] * z[l];
          z[ii] = t / rows[ii][ii];
          inv_norm2 += z[ii] * z[ii];
        }
      }
    }
    const mpfr condition = singular ? mpfr(0) : mpfr(sqrt(r_norm2 * inv_norm2));
    if (singular || condition > max_condition)
      throw InputError("fit of " + std::to_string(harmonics) + " harmonics to " + quoted(detail::visible(wave.name)) +
                       ": the least-squares problem is rank deficient (condition number " +
                       (singular ? std::string("infinite") : format_significant(condition, 3)) +
                       ", above 1e12): expected fewer harmonics or time stamps spread over the period");
    std::vector<mpfr> x(m);
    for (std::size_t ii = m; ii-- > 0;) {
      mpfr t = rows[ii][m];
      for (std::size_t l = ii + 1; l < m; ++l) t -= rows[ii][l] * x[l];
      x[ii] = t / rows[ii][ii];
    }
    a[0] = x[0];
    for (std::size_t k = 1; k <= k_count; ++k) {
      a[k] = x[2 * k - 1];
      b[k] = x[2 * k];
    }
    method << "least squares on phases (t - t0)/T, Householder QR in mpfr at " << digits
           << " digits, condition number " << format_significant(condition, 3);
  }

  FourierFit fit;
  fit.samples = n;
  fit.method = method.str();
  // The coefficients as written (17 digits), and the residual of exactly those.
  std::vector<mpfr> aw(k_count + 1), bw(k_count + 1);
  mpfr big = 0;
  for (const mpfr& v : y) big = std::max(big, mpfr(abs(v)));
  const mpfr noise = big * mpfr("1e-40");
  for (std::size_t k = 0; k <= k_count; ++k) {
    if (abs(a[k]) <= noise) a[k] = 0;
    if (abs(b[k]) <= noise) b[k] = 0;
    const std::string at = format_significant(a[k], coefficient_digits);
    const std::string bt = k == 0 ? std::string("0") : format_significant(b[k], coefficient_digits);
    // The coefficients are the 17-digit decimals written: read back as the file's reader would.
    const Decimal ad = *InputValue::read(at, "fitted coefficient a_" + std::to_string(k) + " of " + quoted(detail::visible(wave.name))).decimal();
    const Decimal bd = *InputValue::read(bt, "fitted coefficient b_" + std::to_string(k) + " of " + quoted(detail::visible(wave.name))).decimal();
    fit.harmonics.push_back({static_cast<unsigned>(k), ad, bd});
    aw[k] = ad.to<mpfr>();
    bw[k] = bd.to<mpfr>();
  }
  mpfr sum2 = 0, worst = 0;
  for (std::size_t j = 0; j < n; ++j) {
    basis(j, c, s);
    mpfr f = aw[0];
    for (std::size_t k = 1; k <= k_count; ++k) f += aw[k] * c[k] + bw[k] * s[k];
    const mpfr r = abs(mpfr(y[j] - f));
    sum2 += r * r;
    if (r > worst) worst = r;
  }
  fit.rms_residual = format_significant(mpfr(sqrt(sum2 / n)), residual_digits);
  fit.max_residual = format_significant(worst, residual_digits);
  return fit;
}

std::string fourier_file_text(const FourierFit& fit, const std::string& source) {
  std::ostringstream out;
  const std::size_t k = fit.harmonics.empty() ? 0 : fit.harmonics.back().k;
  out << "# Fourier series fitted by vibrofric to " << detail::visible(source) << "\n"
      << "# method: " << detail::visible(fit.method) << "\n"
      << "# harmonics K = " << k << ", samples N = " << fit.samples << "\n"
      << "# residual of the samples, in their units: rms " << detail::visible(fit.rms_residual) << ", max "
      << detail::visible(fit.max_residual) << "\n"
      << "k a_k b_k\n";
  for (const auto& h : fit.harmonics) out << h.k << " " << h.a.text() << " " << h.b.text() << "\n";
  return out.str();
}

}  // namespace vibrofric
