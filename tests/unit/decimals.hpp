// Tests' helpers for Decimal values (api/decimal_value.hpp).
#pragma once
#include <string>
#include <vector>

#include "vibrofric/api/decimal_value.hpp"

// The decimals' texts as read.
inline std::vector<std::string> texts(const std::vector<vibrofric::Decimal>& v) {
  std::vector<std::string> out;
  for (const auto& d : v) out.push_back(d.text());
  return out;
}
// A decimal literal.
inline vibrofric::Decimal dec(const char* text) { return *vibrofric::Decimal::read(text); }
inline vibrofric::Decimal dec(const std::string& text) { return *vibrofric::Decimal::read(text); }
