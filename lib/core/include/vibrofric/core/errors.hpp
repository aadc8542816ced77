// Errors of vibrofric: one route for every failure (model.md, "Domain and edge behaviour").
// InputError: bad input (unparsable, NaN, out of domain) — the tool exits 2.
// SolverError: a root finder or integrator that did not converge — the tool exits 1.
// PrecisionError: the working precision cannot resolve the problem, more digits can (the
// precision ladder of evaluate.hpp escalates on it) — the tool exits 1 if it may not escalate.
#pragma once
#include <stdexcept>
#include <string>

namespace vibrofric {

class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The requested (β, γ) lies outside the model's domain, e.g. no contact (γ + max w ≤ 0).
class DomainError : public InputError {
 public:
  using InputError::InputError;
};

// A file named in the input does not exist (Python: FileNotFoundError).
class MissingFileError : public InputError {
 public:
  using InputError::InputError;
};

class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PrecisionError : public SolverError {
 public:
  using SolverError::SolverError;
};

}  // namespace vibrofric
