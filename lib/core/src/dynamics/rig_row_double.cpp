// The curved contact's rig in double, compiled once (core/dynamics/rig_row.hpp).
#include "rig_row_engine.hpp"

namespace vibrofric {
template std::vector<RowSpring<double>> mdr_row(const Profile<double>&, const double&, std::size_t);
template RowRigResult<double> solve_rig_row(const Waveform<double>&, const double&, const double&,
                                            const RigParameters<double>&, const std::vector<RowSpring<double>>&,
                                            const Options&);
template RowRigResult<double> solve_rig_row(const Waveform<double>&, const double&, const double&,
                                            const RigParameters<double>&, const std::vector<RowSpring<double>>&,
                                            const Options&, const std::vector<double>&, std::vector<RowRigSample<double>>&);
}  // namespace vibrofric
