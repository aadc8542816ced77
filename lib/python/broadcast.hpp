// The batch evaluation behind vibrofric.mu and vibrofric.psi: the values at the numpy broadcast of
// beta and gamma, one evaluate_stream with the GIL released (certify=True: exact enclosures).
#pragma once
#include <array>
#include <optional>
#include <string>

#include "common.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/rig.hpp"

namespace vibrofric::python {

struct Evaluation {
  Quantity quantity;
  std::optional<int> digits;
  py::object type;
  ProfileSpec profile;
  unsigned threads = 0;
  std::optional<long long> max_iterations;
  bool escalate = true;
  bool strings = false;
  bool nan_on_error = false;
  bool certify = false;
  std::string profile_text;  // as given, for messages
  std::optional<RigSpec> rig;  // kappa, omega, zeta (rig dynamics), each one number
  // kappa, omega, zeta where one of them is an array: broadcast with beta and gamma (zeta None: 0).
  std::optional<std::array<py::object, 3>> rig_arrays;
  std::optional<InPlaneSpec> inplane;  // longitudinal, phase, in_plane_wave; wave "constant"
};

// Values of `quantity` at the broadcast of beta and gamma (gamma None for psi): one evaluate_stream
// over the points, each made from the arguments by index on the worker threads, each value stored
// into the result as it arrives, the GIL released throughout. With rig_arrays, the broadcast of
// all five, and one evaluate_stream for each rig (κ, Ω, ζ) among the points.
py::object evaluate_broadcast(const py::object& wave_obj, const py::object& beta, const py::object& gamma,
                              const Evaluation& e);

}  // namespace vibrofric::python
