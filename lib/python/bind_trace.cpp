// Binds vibrofric.trace: n and s over one period (flat punch, rig dynamics or a curved profile).
#include <array>
#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/rig.hpp"

namespace vibrofric::python {

namespace {

// Columns of rows, each value printed to `digits` significant digits: decimal strings (object
// arrays), or float64 of those digits (the numbers the tool prints, as Python floats).
template <class Row>
py::array column_of(const std::vector<Row>& rows, const mpfr Row::*field, int digits, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  if (strings) {
    py::array out = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");
    for (py::ssize_t i = 0; i < n; ++i) out[py::int_(i)] = py::str(format_significant(rows[static_cast<std::size_t>(i)].*field, digits));
    return out;
  }
  py::array_t<double> out(n);
  double* p = out.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) p[i] = read_decimal<double>(format_significant(rows[static_cast<std::size_t>(i)].*field, digits));
  return out;
}

// trace_rows as three arrays, phi, n and s.
py::tuple trace_arrays(const std::vector<TraceRow>& rows, int digits, bool strings) {
  return py::make_tuple(column_of(rows, &TraceRow::phi, digits, strings), column_of(rows, &TraceRow::n, digits, strings),
                        column_of(rows, &TraceRow::s, digits, strings));
}

// rig_trace_rows as six arrays, phi, n, s, lag, lag_rate and mode (str).
py::tuple rig_trace_arrays(const std::vector<RigTraceRow>& rows, int digits, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  py::array modes = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");
  for (py::ssize_t i = 0; i < n; ++i) modes[py::int_(i)] = py::str(rig_mode_name(rows[static_cast<std::size_t>(i)].mode));
  return py::make_tuple(column_of(rows, &RigTraceRow::phi, digits, strings), column_of(rows, &RigTraceRow::n, digits, strings),
                        column_of(rows, &RigTraceRow::s, digits, strings), column_of(rows, &RigTraceRow::lag, digits, strings),
                        column_of(rows, &RigTraceRow::lag_rate, digits, strings), modes);
}

// rig_row_trace_rows as nine arrays: phi, n, s, lag, lag_rate and the row's shares stick, slip,
// backward and flight, each number to its own agreed digits.
py::tuple rig_row_trace_arrays(const std::vector<RigRowTraceRow>& rows, int digits, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  const auto column = [&](const Significant RigRowTraceRow::*field) -> py::array {
    if (strings) {
      py::array out = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");
      for (py::ssize_t i = 0; i < n; ++i) out[py::int_(i)] = py::str((rows[static_cast<std::size_t>(i)].*field).text());
      return out;
    }
    py::array_t<double> out(n);
    double* p = out.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) p[i] = read_decimal<double>((rows[static_cast<std::size_t>(i)].*field).text());
    return out;
  };
  return py::make_tuple(column_of(rows, &RigRowTraceRow::phi, digits, strings), column(&RigRowTraceRow::n),
                        column(&RigRowTraceRow::s), column(&RigRowTraceRow::lag), column(&RigRowTraceRow::lag_rate),
                        column(&RigRowTraceRow::stick), column(&RigRowTraceRow::slip), column(&RigRowTraceRow::backward),
                        column(&RigRowTraceRow::flight));
}

py::tuple inplane_trace_arrays(const std::vector<InPlaneTraceRow>& rows, int digits, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  py::array modes = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");
  for (py::ssize_t i = 0; i < n; ++i) modes[py::int_(i)] = py::str(inplane_mode_name(rows[static_cast<std::size_t>(i)].mode));
  return py::make_tuple(column_of(rows, &InPlaneTraceRow::phi, digits, strings),
                        column_of(rows, &InPlaneTraceRow::n, digits, strings),
                        column_of(rows, &InPlaneTraceRow::s_x, digits, strings),
                        column_of(rows, &InPlaneTraceRow::s_y, digits, strings), modes);
}

}  // namespace

void bind_trace(py::module_& m) {
  static constexpr const char* trace_doc = R"doc(trace(wave, beta, gamma=None, *, points=1000, digits=17, strings=False, kappa=None, omega=None, zeta=None, profile='flat', longitudinal=None, transverse=None, phase=None, in_plane_wave=None) -> (phi, n, s), or with kappa and omega (phi, n, s, lag, lag_rate, mode), on a curved profile (phi, n, s, lag, lag_rate, stick, slip, backward, flight), or in plane (phi, n, s_x, s_y, mode)

The normal force n(phi) = max(0, gamma + w(phi)) and the tangential force s(phi) over one period
in the periodic steady state (Fig. 2 of the paper; Eqs. 7-11), flat punch, as the tool's `trace`:
points + 1 equally spaced phases 0, 1/points, ..., 1, both ends of every stick phase and the
contact boundaries (where n = s = 0 exactly), phi ascending. Each value to `digits` significant
digits (computed at digits plus guard digits); three float64 arrays, or arrays of decimal strings
with strings=True. points 2 to 1000000.

With kappa and omega (zeta optional), the rig's periodic state (model.md, "Rig dynamics"), as
`trace --kappa K --omega W --zeta Z`: six arrays (phi, n, s, lag, lag_rate, mode), the body's lag
Y = X - beta phi behind the drive and Y' in units of mu0 k_z A/k_x, and the mode ('stick', 'slip',
'backward', 'flight') as str; both ends of every span (two entries at one phi where a mode ends).

With a curved profile (as mu's profile=, the tool's `trace --profile P`): n and s summed over the
half-row of MDR springs, in the units of the row (mean(s)/mean(n) over the period is mu's value),
at the equally spaced phases and the central spring's contact boundaries. With kappa and omega
too, the rig on the row: nine arrays (phi, n, s, lag, lag_rate, stick, slip, backward, flight),
the lag in units mu0 E* A/G* and the row's shares in each mode; each number to the digits the
row's two sizes agree on.

With longitudinal or transverse (phase and in_plane_wave optional; wave='constant' with
gamma=None for a constant normal force), the in-plane periodic state (model.md, "In-plane and
combined oscillation"), as `trace --longitudinal A --transverse B`: five arrays (phi, n, s_x, s_y,
mode), the tangential force along and across the sliding direction, mode 'stick', 'slip',
'backward' or 'flight'; flat punch.
)doc";
  m.def(
      "trace",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& points,
         const py::object& digits, bool strings, const py::object& kappa, const py::object& omega,
         const py::object& zeta, const py::object& profile, const py::object& longitudinal,
         const py::object& transverse, const py::object& phase, const py::object& in_plane_wave) -> py::tuple {
        TraceRequest request;
        request.profile = to_profile(profile);
        request.beta.value = scalar_value(beta, "beta");
        if (const auto n = optional_int(points, "points")) request.points = *n;
        if (const auto d = optional_int(digits, "digits")) request.digits = *d;
        const bool constant = py::isinstance<py::str>(wave) && wave.cast<std::string>() == "constant";
        const bool amplitude = !longitudinal.is_none() || !transverse.is_none();
        if (constant || amplitude || !phase.is_none() || !in_plane_wave.is_none()) {
          if (!amplitude)
            throw InputError(std::string(constant ? "wave = 'constant'" : phase.is_none() ? "in_plane_wave" : "phase") +
                             " without longitudinal or transverse: give the in-plane amplitude");
          if (!kappa.is_none() || !omega.is_none() || !zeta.is_none())
            throw InputError("kappa/omega with an in-plane oscillation: rig dynamics with an in-plane drive is not modelled");
          if (request.profile.kind != ProfileKind::flat)
            throw InputError("trace with profile = " + py_repr(profile) +
                             " and an in-plane oscillation: the rows are the flat punch's only (mu takes the curved row)");
          const InPlaneSpec spec = inplane_spec(constant, longitudinal, transverse, phase, in_plane_wave);
          WaveSpec w;
          if (constant) {
            if (!gamma.is_none())
              throw InputError("gamma = " + py_repr(gamma) + " with wave 'constant': the normal force is constant (give gamma=None)");
            w.name = "constant";
          } else {
            w = to_wave(wave);
            request.gamma.value = scalar_value(gamma, "gamma");
          }
          std::vector<InPlaneTraceRow> rows;
          {
            py::gil_scoped_release release;
            rows = inplane_trace_rows(w, request, spec);
          }
          return inplane_trace_arrays(rows, request.digits, strings);
        }
        const WaveSpec w = to_wave(wave);
        if (gamma.is_none()) throw InputError("missing gamma: the mean indentation (Eq. 14)");
        request.gamma.value = scalar_value(gamma, "gamma");
        if (!kappa.is_none() || !omega.is_none() || !zeta.is_none()) {
          if (kappa.is_none() || omega.is_none())
            throw InputError(std::string("missing ") + (kappa.is_none() ? "kappa" : "omega") +
                             ": rig dynamics needs kappa and omega (zeta is optional)");
          RigSpec rig;
          rig.kappa = scalar_value(kappa, "kappa");
          rig.omega = scalar_value(omega, "omega");
          if (!zeta.is_none()) rig.zeta = scalar_value(zeta, "zeta");
          if (request.profile.kind != ProfileKind::flat) {
            std::vector<RigRowTraceRow> rows;
            {
              py::gil_scoped_release release;
              rows = rig_row_trace_rows(w, request, rig);
            }
            return rig_row_trace_arrays(rows, request.digits, strings);
          }
          std::vector<RigTraceRow> rows;
          {
            py::gil_scoped_release release;
            rows = rig_trace_rows(w, request, rig);
          }
          return rig_trace_arrays(rows, request.digits, strings);
        }
        std::vector<TraceRow> rows;
        {
          py::gil_scoped_release release;
          rows = trace_rows(w, request);
        }
        return trace_arrays(rows, request.digits, strings);
      },
      "wave"_a, "beta"_a, "gamma"_a = py::none(), py::kw_only(), "points"_a = 1000, "digits"_a = 17, "strings"_a = false,
      "kappa"_a = py::none(), "omega"_a = py::none(), "zeta"_a = py::none(), "profile"_a = "flat",
      "longitudinal"_a = py::none(), "transverse"_a = py::none(), "phase"_a = py::none(), "in_plane_wave"_a = py::none(),
      trace_doc);
}

}  // namespace vibrofric::python
