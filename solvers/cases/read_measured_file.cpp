#include "cases/read_measured_file.hpp"

#include <fmt/format.h>

#include <climits>
#include <vector>

#include "common/errors.hpp"
#include "identify/uff58.hpp"

namespace bb {

namespace {

// A frf file of phases alone says through `phase_of` what they are the phase of (an amplitude
// column's unit would have said it).
void phases_alone(TomlReader& r, const std::filesystem::path& file, MeasuredData& data) {
  const bool alone = data.kind == DataKind::frf && !data.has("amplitude");
  if (!alone) {
    if (r.has("phase_of"))
      r.fail("phase_of", fmt::format("{} has an amplitude column, whose unit says what its phase is of: leave out "
                                     "phase_of",
                                     file.string()));
    return;
  }
  if (!r.has("phase_of"))
    r.fail("file", fmt::format("{} holds phases without an amplitude column: say what they are the phase of with "
                               "phase_of = \"displacement\", \"velocity\" or \"acceleration\"",
                               file.string()));
  const std::string of = r.choice("phase_of", {"displacement", "velocity", "acceleration"});
  phase_to_displacement(data, of == "displacement" ? 0 : of == "velocity" ? 1 : 2);
}

}  // namespace

MeasuredFile read_measured_file(TomlReader& r, const std::filesystem::path& file, DataKind kind, bool phases_read) {
  MeasuredFile out;
  // A Universal File may hold several levels, one dataset 58 each.
  const std::optional<long> dataset = r.optional_integer("dataset", 1, INT_MAX);
  if (dataset && !is_universal_file(file))
    r.fail("dataset", "picks a dataset 58 of a Universal File (.uff, .unv); a CSV file holds one curve");
  if (dataset && kind != DataKind::frf) r.fail("dataset", "a Universal File's datasets are frf data (kind = \"frf\")");
  // A rig's force (reference) channel as its own record: each point's force.
  const std::optional<long> force_dataset = r.optional_integer("force_dataset", 1, INT_MAX);
  if (force_dataset && !dataset)
    r.fail("force_dataset", "pairs a force record with the response record `dataset`: give dataset too");
  if (force_dataset && *force_dataset == *dataset)
    r.fail("force_dataset", "is the response record itself: name the force record");
  MeasuredReadOptions options;
  if (r.has("natural_frequency_hz")) {
    if (dataset) r.fail("natural_frequency_hz", "a Universal File's abscissa is in Hz: leave out natural_frequency_hz");
    options.natural_frequency_hz = r.positive("natural_frequency_hz");
  }
  std::vector<Uff58Function> functions;
  try {
    if (dataset)
      functions = read_uff58(file);
    else
      out.data = read_measured_data(file, kind, options);
  } catch (const InputError& e) {
    r.fail("file", e.what());  // the case, line and key that named the file, then the file's own error
  }
  out.dataset = dataset;
  if (!dataset) {
    if (options.natural_frequency_hz && !out.data.frequency_ratio)
      r.fail("natural_frequency_hz", fmt::format("{}'s frequency column is in {}, not ratios ('-'): leave out "
                                                 "natural_frequency_hz",
                                                 file.string(), out.data.units.at("frequency").symbol));
    if (phases_read || r.has("phase_of")) phases_alone(r, file, out.data);
    return out;
  }
  const auto within_file = [&](const char* key, long index) {
    if (static_cast<size_t>(index) > functions.size())
      r.fail(key,
             fmt::format("dataset {} asked, but {} holds {} dataset(s) 58", index, file.string(), functions.size()));
  };
  within_file("dataset", *dataset);
  if (force_dataset) within_file("force_dataset", *force_dataset);
  try {
    const Uff58Function& response = functions[static_cast<size_t>(*dataset - 1)];
    out.data = force_dataset ? uff58_response_with_force(response, static_cast<int>(*dataset),
                                                         functions[static_cast<size_t>(*force_dataset - 1)],
                                                         static_cast<int>(*force_dataset), file)
                             : uff58_frf(response, file, static_cast<int>(*dataset));
  } catch (const InputError& e) {
    r.fail(force_dataset ? "force_dataset" : "dataset", e.what());
  }
  return out;
}

}  // namespace bb
