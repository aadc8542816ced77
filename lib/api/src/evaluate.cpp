#include "vibrofric/api/evaluate.hpp"

#include <limits>

namespace vibrofric {

std::optional<NumberType> number_type_named(const std::string& text) {
  if (text == "double") return NumberType::float64;
  if (text == "long-double") return NumberType::float80;
  if (text == "cpp_bin_float_50") return NumberType::bin50;
  if (text == "cpp_bin_float_100") return NumberType::bin100;
  if (text == "mpfr") return NumberType::mpfr;
  return std::nullopt;
}

std::vector<std::string> number_type_names() {
  std::vector<std::string> names;
  for (NumberType t : {NumberType::float64, NumberType::float80, NumberType::bin50, NumberType::bin100, NumberType::mpfr})
    names.push_back(number_type_name(t));
  return names;
}

std::string number_type_name(NumberType t) {
  switch (t) {
    case NumberType::float64: return "double";
    case NumberType::float80: return "long-double";
    case NumberType::bin50: return "cpp_bin_float_50";
    case NumberType::bin100: return "cpp_bin_float_100";
    case NumberType::mpfr: return "mpfr";
  }
  return "?";
}

int output_digits(const Precision& p) {
  switch (p.type) {
    case NumberType::float64: return std::numeric_limits<double>::max_digits10;
    case NumberType::float80: return std::numeric_limits<long double>::max_digits10;
    case NumberType::bin50: return 50;
    case NumberType::bin100: return 100;
    case NumberType::mpfr: return p.digits;
  }
  return p.digits;
}

namespace {
// The digits printed, after the request's are checked.
int checked_output_digits(const Precision& precision) {
  if (precision.type == NumberType::mpfr &&
      (precision.digits < min_digits || precision.digits > max_digits))
    throw InputError("digits = " + std::to_string(precision.digits) + ": expected " +
                     std::to_string(min_digits) + " to " + std::to_string(max_digits));
  return output_digits(precision);
}
}  // namespace

Evaluated evaluate_one(const WaveSpec& wave, Quantity q, const Point& point, const Precision& precision,
                       const BatchOptions& options) {
  const int digits = checked_output_digits(precision);
  switch (precision.type) {
    case NumberType::float64: return detail::evaluate_one_typed<double>(wave, q, point, digits, options);
    case NumberType::float80: return detail::evaluate_one_typed<long double>(wave, q, point, digits, options);
    case NumberType::bin50: return detail::evaluate_one_typed<bin50>(wave, q, point, digits, options);
    case NumberType::bin100: return detail::evaluate_one_typed<bin100>(wave, q, point, digits, options);
    case NumberType::mpfr: return detail::evaluate_one_typed<mpfr>(wave, q, point, digits, options);
  }
  throw std::logic_error("evaluate_one: unknown number type");
}

void evaluate_stream(const WaveSpec& wave, Quantity q, std::size_t count,
                     const std::function<Point(std::size_t)>& point, const Precision& precision,
                     const BatchOptions& options, const std::function<void(std::size_t, const StreamValue&)>& sink) {
  const int digits = checked_output_digits(precision);
  switch (precision.type) {
    case NumberType::float64: return detail::evaluate_stream_typed<double>(wave, q, count, point, digits, options, sink);
    case NumberType::float80: return detail::evaluate_stream_typed<long double>(wave, q, count, point, digits, options, sink);
    case NumberType::bin50: return detail::evaluate_stream_typed<bin50>(wave, q, count, point, digits, options, sink);
    case NumberType::bin100: return detail::evaluate_stream_typed<bin100>(wave, q, count, point, digits, options, sink);
    case NumberType::mpfr: return detail::evaluate_stream_typed<mpfr>(wave, q, count, point, digits, options, sink);
  }
}

std::vector<std::string> evaluate(const WaveSpec& wave, Quantity q, const std::vector<Point>& points,
                                  const Precision& precision, const BatchOptions& options) {
  std::vector<std::string> out(points.size());
  evaluate_stream(
      wave, q, points.size(), [&](std::size_t i) { return points[i]; }, precision, options,
      [&](std::size_t i, const StreamValue& value) { out[i] = value.text; });
  return out;
}

}  // namespace vibrofric
