// Measured FRFs in Universal File Format dataset 58 (function at a nodal DOF, ASCII), the format rig
// software (LMS Test.Lab, Simcenter, ...) exports: read into the measured-data form of
// identify/measured_data.hpp (columns frequency, amplitude, phase, in SI) and written from it.
//
// A dataset is "    -1" / "    58" / records 1-12 / "    -1"; records 1-5 are ID lines, 6 names the
// function type and the response / reference DOFs, 7 the data type (2 real, 4 real double, 5
// complex, 6 complex double), the number of values and the abscissa spacing, 8-11 the axes' data
// characteristics (specific data type, unit exponents, axis label, axis unit label), 12 the values.
// A record whose ordinate is a force (no denominator) is a force record: a rig's reference
// channel, paired with a response record by uff58_response_with_force.
// Units come from the file: the unit labels of records 8 (abscissa), 9 (numerator) and 10
// (denominator) when they name known units (identify/measured_data.hpp, parse_unit), else the
// specific data types (18 frequency -> Hz, 8 displacement -> m, 13 excitation force -> N) in SI.
// Values are split on blanks (every standard field width leaves one). Other datasets are skipped.
#pragma once
#include <complex>
#include <filesystem>
#include <string>
#include <vector>

#include "identify/measured_data.hpp"

namespace bb {

struct Uff58Function {
  std::vector<std::string> id_lines;  // records 1-5
  int function_type = 4;              // 1 time response, 2 auto spectrum, 3 cross spectrum, 4 FRF, ...
  long response_node = 1, reference_node = 1;
  int response_direction = 1, reference_direction = 1;  // 1..3 = +X..+Z, negative = minus
  std::vector<double> abscissa;                         // as written, in its unit
  std::vector<std::complex<double>> values;             // as written, in the numerator / denominator units
  Unit abscissa_unit, ordinate_unit;                    // ordinate: numerator / denominator composed
  int line = 0;                                         // where the dataset starts (its first "-1")
};

// Every dataset 58 of the file, in order. Throws InputError "file:line: dataset 58 #k, record r: ..."
// on a malformed record, a value count that differs from record 7, a non-finite value, or units
// that cannot be determined; and when the file holds no dataset 58.
std::vector<Uff58Function> read_uff58(const std::filesystem::path& file);

// Dataset 58 number `index` (1-based, in file order) of `file` as frf data: frequency [Hz],
// amplitude [compliance or length], phase [rad] of the complex values (real data: phase 0 left
// out). Validated as the CSV reader validates an frf file (frequencies strictly increasing or
// strictly decreasing: one stepped sine up or down; positive amplitudes); rows point at the record 12 line of each
// value. A rig's several levels are several datasets of one file.
MeasuredData uff58_frf(const Uff58Function& function, const std::filesystem::path& file, int index);

// A rig's two channels of one stepped sine: the response record (a displacement, velocity or
// acceleration spectrum) and the force record (the reference channel, a force spectrum) at the same
// frequencies, as frf data with a force per point: frequency, amplitude, phase (the response's to the
// force, rad), force [N], force_phase [rad]. Throws InputError naming the file, line and dataset
// when a record is of the wrong kind or the two differ in their frequencies.
MeasuredData uff58_response_with_force(const Uff58Function& response, int response_index, const Uff58Function& force,
                                       int force_index, const std::filesystem::path& file);

// The file's first dataset 58 as frf data (uff58_frf).
MeasuredData read_uff58_frf(const std::filesystem::path& file);

// Writes frf data (frequency, amplitude, optional phase) as one dataset 58 of complex double
// values, uneven abscissa, units labelled in records 8-10; with a force per point (column force,
// optional force_phase), as two: the force record, then the displacement record (spectra, function
// type 12), as a rig's reference and response channels. Throws InputError when it cannot write.
void write_uff58_frf(const MeasuredData& data, const std::filesystem::path& file, const std::string& title);

// True for the extensions read as Universal Files (.uff, .unv, any case).
bool is_universal_file(const std::filesystem::path& file);

}  // namespace bb
