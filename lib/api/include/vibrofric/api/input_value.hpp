// One number given to the library (README, "Numbers"): a decimal as written, read once where its
// text enters (a flag, a Python argument, a file field: read below), or a value another layer
// computed (physical's β from SI inputs), with the label messages name it by; or none.
#pragma once
#include <iosfwd>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "vibrofric/api/decimal_value.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

class InputValue {
 public:
  InputValue() = default;
  InputValue(Decimal d) : held_(std::move(d)) {}  // NOLINT: a decimal is an input as it stands
  // `text` read by the one grammar: InputError naming `what` outside it or beyond double's range
  // (check_decimal, catalogue.hpp), the same decision in every number type.
  static InputValue read(const std::string& text, const std::string& what);
  // A computed value, taken as it is by every number type (each rounds it once); `label` names it
  // in messages and is never read back.
  static InputValue computed(mpfr value, std::string label) {
    InputValue v;
    v.held_ = Computed{std::move(value), std::move(label)};
    return v;
  }

  bool given() const { return !std::holds_alternative<std::monostate>(held_); }
  const Decimal* decimal() const { return std::get_if<Decimal>(&held_); }
  const mpfr* computed_value() const {
    const auto* c = std::get_if<Computed>(&held_);
    return c ? &c->value : nullptr;
  }
  // The text as typed, a computed value's label, "" for none.
  const std::string& text() const {
    static const std::string none;
    if (const auto* d = decimal()) return d->text();
    if (const auto* c = std::get_if<Computed>(&held_)) return c->label;
    return none;
  }
  // In Real: a decimal correctly rounded (at mpfr's current precision), a computed value rounded
  // once; 0 for none.
  template <class Real>
  Real to() const {
    if (const auto* d = decimal()) return d->template to<Real>();
    if (const mpfr* v = computed_value()) return detail::rounded<Real>(*v);
    return Real(0);
  }

 private:
  struct Computed {
    mpfr value;
    std::string label;
  };
  std::variant<std::monostate, Decimal, Computed> held_;
};

// Its text(), for messages.
std::ostream& operator<<(std::ostream& out, const InputValue& v);

// An input and the name its caller knows it by (the tool's "--E1", Python's "E1"), which every
// message about it uses.
struct NamedInput {
  InputValue value;
  std::string name;
  bool given() const { return value.given(); }
  const std::string& text() const { return value.text(); }
};

}  // namespace vibrofric
