// Decimal (decimal_value.hpp): the one reader of decimal text, exact values and comparison.
#include "vibrofric/api/decimal_value.hpp"
#include "vibrofric/api/exact_input.hpp"

#include <boost/multiprecision/gmp.hpp>

#include <algorithm>
#include <ostream>

#include "vibrofric/core/errors.hpp"

namespace vibrofric {

// Scanned by hand: std::regex cost several µs per 60-digit number, more than a double evaluation
// (bench/README.md).
std::optional<Decimal> Decimal::read(const std::string& t) {
  Decimal d;
  std::size_t i = 0;
  const std::size_t n = t.size();
  auto digits = [&](std::string* into) {
    const std::size_t start = i;
    while (i < n && t[i] >= '0' && t[i] <= '9') {
      if (into) *into += t[i];
      ++i;
    }
    return i - start;
  };
  if (i < n && (t[i] == '+' || t[i] == '-')) d.negative_ = t[i++] == '-';
  std::string significand;
  std::size_t mantissa = digits(&significand);
  long scale = 0;  // digits after the point
  if (i < n && t[i] == '.') {
    ++i;
    const std::size_t fraction = digits(&significand);
    mantissa += fraction;
    scale = static_cast<long>(fraction);
  }
  if (mantissa == 0) return std::nullopt;
  long exponent = 0;
  if (i < n && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < n && (t[i] == '+' || t[i] == '-')) negative_exponent = t[i++] == '-';
    std::string e;
    const std::size_t count = digits(&e);
    if (count == 0 || count > 9) return std::nullopt;
    exponent = std::stol(e);
    if (negative_exponent) exponent = -exponent;
  }
  if (i != n) return std::nullopt;
  d.text_ = t;
  d.zero_ = significand.find_first_not_of('0') == std::string::npos;
  d.exponent_ = exponent - scale;
  return d;
}

std::string Decimal::digits() const {
  std::string out;
  for (const char c : text_) {
    if (c == 'e' || c == 'E') break;
    if (c >= '0' && c <= '9' && (c != '0' || !out.empty())) out += c;
  }
  return out;
}

int Decimal::written_digits() const {
  int n = 0;
  for (const char c : text_) {
    if (c == 'e' || c == 'E') break;
    if (c >= '0' && c <= '9') ++n;
  }
  return n;
}

exact::Rational rational(const Decimal& d, const std::string& what) {
  if (d.is_zero()) return 0;
  const long power = d.exponent();
  if (power > max_rational_exponent || power < -max_rational_exponent - static_cast<long>(d.digits().size()))
    throw InputError(what + " '" + d.text() + "': its exponent is beyond ±" + std::to_string(max_rational_exponent) +
                     ", too large for an exact rational");
  using Integer = boost::multiprecision::mpz_int;
  // mpz_int reads a leading 0 as octal: digits() has none.
  const Integer num(d.digits()), ten = pow(Integer(10), static_cast<unsigned>(power < 0 ? -power : power));
  const exact::Rational r = power < 0 ? exact::Rational(num, ten) : exact::Rational(num * ten);
  return d.negative() ? exact::Rational(-r) : r;
}

std::ostream& operator<<(std::ostream& out, const Decimal& d) { return out << d.text(); }

int compare(const Decimal& a, const Decimal& b) {
  const int sa = a.is_zero() ? 0 : (a.negative() ? -1 : 1), sb = b.is_zero() ? 0 : (b.negative() ? -1 : 1);
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  // Magnitudes: the power of ten of the leading digit first, then the digits, padded with zeros.
  const long lead_a = a.exponent() + static_cast<long>(a.digits().size());
  const long lead_b = b.exponent() + static_cast<long>(b.digits().size());
  int magnitude = 0;
  if (lead_a != lead_b) {
    magnitude = lead_a < lead_b ? -1 : 1;
  } else {
    std::string x = a.digits(), y = b.digits();
    const std::size_t length = std::max(x.size(), y.size());
    x.resize(length, '0');
    y.resize(length, '0');
    magnitude = x < y ? -1 : (x > y ? 1 : 0);
  }
  return sa * magnitude;
}

std::string exact_sum_text(const std::vector<const Decimal*>& terms) {
  using Integer = boost::multiprecision::mpz_int;
  long low = 0;
  for (std::size_t k = 0; k < terms.size(); ++k) low = k == 0 ? terms[k]->exponent() : std::min(low, terms[k]->exponent());
  Integer sum = 0;
  for (const Decimal* d : terms) {
    // mpz_int reads a leading 0 as octal: digits() has none.
    const Integer m = d->is_zero() ? Integer(0) : Integer(d->digits());
    const Integer scaled = m * boost::multiprecision::pow(Integer(10), static_cast<unsigned>(d->exponent() - low));
    sum += d->negative() ? Integer(-scaled) : scaled;
  }
  return sum.str() + "e" + std::to_string(low);
}

}  // namespace vibrofric
