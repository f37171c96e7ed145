// The operating deflection of a linear forced response over the whole mesh: the complex
// displacement of every node at a frequency, by the modal sum (eq 3.32) of the full model's kept
// modes under the analysis's forces, for ParaView (report/vtk_files.hpp).
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "analysis/frf_spec.hpp"
#include "analysis/modal_analysis.hpp"
#include "model/model.hpp"

namespace bb {

// Modal damping ratio of each mode of circular frequency omega (modal ratios, or Rayleigh's).
Eigen::VectorXd modal_zetas(const FrfDamping& damping, const Eigen::VectorXd& omega);

// n_nodes x dim complex amplitudes U (u = Re(U e^{i w t})) at each frequency [Hz]. Without the
// residual flexibility of the modes left out (that term is known at the response DOFs only), so at a
// response DOF it equals the sweep's value when the analysis has residual_flexibility = false.
std::vector<Eigen::MatrixXcd> operating_deflections(const Model& model, const FrfSpec& spec, const ModalResult& modal,
                                                    const std::vector<double>& frequencies_hz);

}  // namespace bb
