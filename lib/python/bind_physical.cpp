// Binds vibrofric.physical: the tool's `physical` from SI inputs, scalars or arrays that broadcast.
#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/commands.hpp"

namespace vibrofric::python {

namespace {

BatchOptions solver_controls(const py::object& max_iterations, bool escalate) {
  BatchOptions options;
  options.escalate = escalate;
  if (const auto mi = optional_int(max_iterations, "max_iterations")) {
    if (*mi < 1 || *mi > root_iterations_limit)
      throw InputError("max_iterations = " + std::to_string(*mi) + ": expected 1 to " + std::to_string(root_iterations_limit));
    options.solver.max_root_iterations = static_cast<std::uintmax_t>(*mi);
  }
  return options;
}

// `physical` (commands.hpp): the inputs as decimal texts of the Python values, named by their
// keywords; the outputs by name, shape a string and the rest in the Form of the precision.
py::dict physical_dict(const WaveSpec& wave, const PhysicalRequest& request, const Precision& precision,
                       const BatchOptions& options, bool strings) {
  PhysicalOutputs record;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    record = physical_point(wave, request, precision, options, &warnings);
  }
  // Implausible inputs (a modulus in GPa read as Pa, ...): a UserWarning each, the values still computed.
  for (const auto& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();  // warnings as errors
  const Converter convert(result_form(precision, strings), precision);
  py::dict d;
  for (const auto& output : record)
    d[py::str(output.name)] = output.name == "shape" ? py::object(py::str(output.word)) : convert(output.text());
  return d;
}

}  // namespace

void bind_physical(py::module_& m) {
  static constexpr const char* physical_doc = R"doc(physical(wave, *, E1, nu1, E2, nu2, v0, f, A=None, mu0, u_mean=None, F_N=None, G1=None, G2=None, shape="flat", radius=None, R=None, half_angle=None, flat_radius=None, unit=None, mass=None, k_system=None, damping=None, u_x=None, u_y=None, phase=None, in_plane_wave=None, digits=None, type=None, max_iterations=None, escalate=True, strings=False, nan_on_error=False, trace=False, points=None) -> dict

The tool's `physical` from SI inputs: effective moduli and stiffnesses (Eq. 1), beta = G* v0 /
(mu0 E* A f) (Eq. 5), gamma = u_mean/A (Eq. 14) -- or gamma solving <F_N>(gamma) = F_N for a given
mean normal load -- then mu/mu0 (Eq. 15), mu, the mean forces, the peak load and contact
pressures, beta_c (Eq. 6) and the fractions of the period in contact and (flat punch) in stick.
Curved indenters by MDR (model.md).

E1, E2 Pa > 0; nu1, nu2 in (-1, 0.5]; G1, G2 Pa (default E/(2(1 + nu))); v0 m/s; f Hz; A m
(zero-to-peak), or for a samples wave unit ('m', 'mm', 'um', 'nm': its values' unit; A is then
half their peak-to-peak, returned as A_m); mu0 > 0; exactly one of u_mean (m, mean indentation) and F_N (N, mean load).
shape 'flat' (radius m), 'sphere' (R m), 'cone' (half_angle degrees), 'wearflat' (R, flat_radius m)
or 'profile:FILE' (heights in m). Numbers as for mu() (floats by their shortest decimal text).
mass kg and k_system N/m (both; damping N s/m optional): tangential rig dynamics (model.md), a body
of mass m on the apparatus' spring; then kappa, omega, zeta and the rig's stick, slip and flight
fractions and Floquet multiplier follow contact_fraction. On a curved shape the body carries the
MDR row: kappa and omega of k_x_max_N_per_m = 2 a_max G* (every spring touching), any gamma.
u_x, u_y (m, zero-to-peak, >= 0), phase (periods) and in_plane_wave (a catalogue wave): in-plane
oscillation (model.md), a_l = G* u_x/(mu0 E* A) returned as longitudinal and transverse; mu is then
the in-plane model's, with F_y_mean_N and the flat punch's fractions. wave = 'constant' with F_N: a
constant normal load (flat punch, no A or u_mean), beta = k_x v0/(mu0 F_N f), a = k_x u/(mu0 F_N).

Returns a dict with exactly the tool's output names, in its order: shape, A_m (given unit),
E_star_Pa, G_star_Pa, k_z_N_per_m and k_x_N_per_m (flat) or contact_radius_max_m (curved), lambda
(wearflat), beta, gamma, u_mean_m (given F_N), mu_over_mu0, mu, F_N_mean_N, F_x_mean_N, at the
deepest instant F_N_peak_N, p_mean_peak_Pa and p_max_peak_Pa (Hertz on the sphere; inf where the
elastic pressure is unbounded: the punch's rim, the cone's tip, a profile's kink), beta_c (inf:
stick at every beta), contact_fraction (curved: the central spring's) and stick_fraction (curved: the
springs' stick shares averaged over the MDR half-row to the largest contact radius). Values as float (type None/'double': the
nearest double of the tool's --type double text), numpy.longdouble, or for digits=D mpmath.mpf /
decimal strings equal to `vibrofric physical --digits D --format json`; strings=True gives the
tool's strings for every type. ValueError with the library's message (naming the input by its keyword).

Any numeric input may be an array: the inputs broadcast (numpy's rules) and every output but shape
is an array of the broadcast shape (float64, longdouble, or object arrays of mpf / strings), each
element the scalar call's value. An element that fails raises its error prefixed with its index
('at index (2,): ...'), or with nan_on_error=True (scipy's convention) is NaN (None in object
arrays) while the others answer.

trace=True (the tool's physical --trace, points as its --points, default 1000): one period of the
point in SI instead, a dict of arrays t_s, F_N_N, F_x_N and u_m (the tip's indentation, negative
off the surface), each to digits significant digits (17 by default): float64, or strings with
strings=True. With a rig (mass, k_system) also x_m (the body's position, the drive at v0 t) and
F_s_N (the apparatus' force on the body, what a force sensor in the holder reads), each to the
digits its inputs carry (on a curved shape those the row's two sizes agree on). Not with an
in-plane drive.
)doc";
  m.def(
      "physical",
      [](const py::object& wave, const py::object& E1, const py::object& nu1, const py::object& E2,
         const py::object& nu2, const py::object& v0, const py::object& f, const py::object& A, const py::object& mu0,
         const py::object& u_mean, const py::object& F_N, const py::object& G1, const py::object& G2,
         const py::object& shape, const py::object& radius, const py::object& R, const py::object& half_angle,
         const py::object& flat_radius, const py::object& unit, const py::object& mass, const py::object& k_system,
         const py::object& damping, const py::object& u_x, const py::object& u_y, const py::object& phase,
         const py::object& in_plane_wave, const py::object& digits, const py::object& type,
         const py::object& max_iterations, bool escalate, bool strings, bool nan_on_error, bool trace,
         const py::object& points) {
        // 'constant': no normal oscillation, the load F_N (physical_constant); else a wave to read.
        const bool constant = py::isinstance<py::str>(wave) && wave.cast<std::string>() == "constant";
        WaveSpec w;
        if (constant)
          w.name = "constant";
        else
          w = to_wave(wave);
        if (!in_plane_wave.is_none() && !py::isinstance<py::str>(in_plane_wave))
          throw py::type_error("in_plane_wave = " + py_repr(in_plane_wave) + ": expected a catalogue wave's name");
        if (!unit.is_none() && !py::isinstance<py::str>(unit))
          throw py::type_error("unit = " + py_repr(unit) + ": expected 'm', 'mm', 'um' or 'nm'");
        const Precision precision = to_precision(optional_int(digits, "digits"), type);
        const BatchOptions options = solver_controls(max_iterations, escalate);
        if (!py::isinstance<py::str>(shape))
          throw py::type_error("shape = " + py_repr(shape) + ": expected 'flat', 'sphere', 'cone', 'wearflat' or 'profile:FILE'");
        // The keywords are the request's member names, which its messages use.
        const std::map<std::string, const py::object*> given{
            {"E1", &E1},   {"nu1", &nu1},       {"E2", &E2},   {"nu2", &nu2},   {"G1", &G1},
            {"G2", &G2},   {"v0", &v0},         {"f", &f},     {"A", &A},       {"u_mean", &u_mean},
            {"F_N", &F_N}, {"mu0", &mu0},       {"radius", &radius}, {"R", &R}, {"half_angle", &half_angle},
            {"flat_radius", &flat_radius}, {"mass", &mass}, {"k_system", &k_system}, {"damping", &damping},
            {"u_x", &u_x}, {"u_y", &u_y}, {"phase", &phase}};
        auto request_of = [&](const std::map<std::string, py::object>& values) {
          PhysicalRequest request;
          request.shape.text = shape.cast<std::string>();
          if (!unit.is_none()) request.unit.text = unit.cast<std::string>();
          if (!in_plane_wave.is_none()) request.in_plane_wave.text = in_plane_wave.cast<std::string>();
          request.constant_normal = constant;
          for (const auto& input : request.inputs()) {
            const auto it = values.find(input.member);
            if (it != values.end() && input.number) input.number->value = scalar_value(it->second, input.member);
          }
          return request;
        };
        const py::module_ np = py::module_::import("numpy");
        std::vector<std::string> names;
        py::list arrays;
        bool broadcast = false;
        for (const auto& [name, value] : given)
          if (!value->is_none()) {
            names.push_back(name);
            arrays.append(*value);
            broadcast = broadcast || (!py::isinstance<py::str>(*value) && np.attr("ndim")(*value).cast<int>() > 0);
          }
        if (trace) {
          // One period in SI (the tool's physical --trace): t_s, F_N_N, F_x_N, u_m (a rig: x_m, F_s_N).
          if (broadcast) throw InputError("trace=True with array inputs: expected one point");
          if (!type.is_none()) throw InputError("trace=True gives digits significant digits (17 by default): expected no type");
          std::map<std::string, py::object> values;
          for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = arrays[k];
          const int d = optional_int(digits, "digits").value_or(17);
          std::vector<PhysicalTraceRow> rows;
          {
            const PhysicalRequest request = request_of(values);
            py::gil_scoped_release release;
            rows = physical_trace(w, request, optional_int(points, "points").value_or(1000), d, options);
          }
          py::dict out;
          const auto column = [&](const char* name, auto text_of) {
            py::list values;
            for (const auto& r : rows) {
              const std::string text = text_of(r);
              values.append(strings ? py::object(py::str(text)) : py::object(py::float_(std::strtod(text.c_str(), nullptr))));
            }
            out[name] = np.attr("array")(values, "dtype"_a = strings ? "object" : "float64");
          };
          for (const auto& [name, field] : {std::pair<const char*, Significant PhysicalTraceRow::*>{"t_s", &PhysicalTraceRow::t_s},
                                            {"F_N_N", &PhysicalTraceRow::F_N_N}, {"F_x_N", &PhysicalTraceRow::F_x_N},
                                            {"u_m", &PhysicalTraceRow::u_m}})
            column(name, [field = field](const PhysicalTraceRow& r) { return (r.*field).text(); });
          if (!rows.empty() && rows.front().x_m) {
            column("x_m", [](const PhysicalTraceRow& r) { return r.x_m->text(); });
            column("F_s_N", [](const PhysicalTraceRow& r) { return r.F_s_N->text(); });
          }
          return py::object(out);
        }
        if (!points.is_none()) throw InputError("points without trace=True: expected trace=True");
        if (!broadcast) {
          std::map<std::string, py::object> values;
          for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = arrays[k];
          return py::object(physical_dict(w, request_of(values), precision, options, strings));
        }
        // Arrays broadcast against each other (numpy's rules) and the scalars: every output an
        // array of the broadcast shape (shape stays one string). A failing element is NaN (None
        // for strings) with nan_on_error, else its error names its index.
        const py::list parts = np.attr("broadcast_arrays")(*arrays);
        const py::tuple dims = parts[0].attr("shape");
        const std::size_t count = parts[0].attr("size").cast<std::size_t>();
        std::vector<std::optional<py::dict>> rows(count);
        for (std::size_t i = 0; i < count; ++i) {
          std::map<std::string, py::object> values;
          for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = parts[k].attr("flat")[py::int_(i)].attr("item")();
          const auto where = [&] { return "at index " + py::str(np.attr("unravel_index")(i, dims)).cast<std::string>() + ": "; };
          try {
            rows[i] = physical_dict(w, request_of(values), precision, options, strings);
          } catch (const InputError& e) {
            if (!nan_on_error) throw InputError(where() + e.what());
          } catch (const SolverError& e) {
            if (!nan_on_error) throw SolverError(where() + e.what());
          }
        }
        const auto first = std::find_if(rows.begin(), rows.end(), [](const auto& r) { return r.has_value(); });
        if (first == rows.end())
          throw InputError("physical: every element failed (nan_on_error = True): expected at least one to answer");
        py::dict out;
        const bool objects = strings || result_form(precision, strings) == Form::mpf;
        for (const auto& item : **first) {
          const py::str name = py::reinterpret_borrow<py::str>(item.first);
          if (name.cast<std::string>() == "shape") {
            out[name] = item.second;
            continue;
          }
          py::list column;
          for (const auto& r : rows)
            column.append(r ? py::object((*r)[name])
                            : objects ? py::object(py::none()) : py::object(py::float_(std::numeric_limits<double>::quiet_NaN())));
          const char* dtype = objects ? "object" : precision.type == NumberType::float80 ? "longdouble" : "float64";
          out[name] = np.attr("array")(column, "dtype"_a = dtype).attr("reshape")(dims);
        }
        return py::object(out);
      },
      "wave"_a, py::kw_only(), "E1"_a, "nu1"_a, "E2"_a, "nu2"_a, "v0"_a, "f"_a, "A"_a = py::none(), "mu0"_a,
      "u_mean"_a = py::none(), "F_N"_a = py::none(), "G1"_a = py::none(), "G2"_a = py::none(), "shape"_a = "flat",
      "radius"_a = py::none(), "R"_a = py::none(), "half_angle"_a = py::none(), "flat_radius"_a = py::none(),
      "unit"_a = py::none(), "mass"_a = py::none(), "k_system"_a = py::none(), "damping"_a = py::none(),
      "u_x"_a = py::none(), "u_y"_a = py::none(), "phase"_a = py::none(), "in_plane_wave"_a = py::none(),
      "digits"_a = py::none(), "type"_a = py::none(), "max_iterations"_a = py::none(), "escalate"_a = true,
      "strings"_a = false, "nan_on_error"_a = false, "trace"_a = false, "points"_a = py::none(), physical_doc);
}

}  // namespace vibrofric::python
