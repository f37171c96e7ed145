// How a resonance peak moves with the model's parameters: d(frequency)/d log p and d(amplitude)/d
// log p of a polished peak, so that a calibration against peaks needs one run per Jacobian instead
// of 2 n + 1.
//
// The peak of the component c(omega, p) satisfies dc/domega = 0, so by the implicit function
// theorem d omega*/dp = -c_{omega p} / c_{omega omega}. c_p and c_omega come exactly from the
// solution's sensitivities (hbm/sensitivity.hpp; omega enters as dC = C / omega, dM = 2 M / omega)
// at omega* (1 +- eps); their central differences give c_{omega p} and c_{omega omega}, with an
// error of order eps where second differences of c would have eps^2 in a denominator. The amplitude
// follows the peak: d a*/dp = a_p + a_omega d omega*/dp.
#pragma once
#include <vector>

#include "forced/hbm_level.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/sensitivity.hpp"

namespace bb {

// Fills peak.frequency_hz_dlog and peak.amplitude_dlog (one entry per derivative) from the peak's
// converged solution on `system`; NaN entries where the peak is not a smooth maximum (a corner of
// the curve, a solve beside it that fails, a singular Jacobian). A maximum at an end of the band
// (`at_band_end`) stays there: its frequency does not move and its amplitude changes as at a fixed
// frequency.
void add_peak_sensitivities(const PreparedHbm& p, const hbm::HarmonicBalance& system, int kind,
                            const std::vector<hbm::ModelDerivative>& derivatives, bool at_band_end, HbmPeak& peak);

}  // namespace bb
