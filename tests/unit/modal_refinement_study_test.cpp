// The modal refinement study (study/modal_refinement) on a small clamped bar.
#include <gtest/gtest.h>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "study/modal_refinement.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

const char* kBar = R"(
[case]
name = "bar_study"
[material]
E = 2.1e11
nu = 0.3
rho = 7850.0
[mesh]
kind = "hex_blocks"
element = "hex20"
[[mesh.block]]
corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.05, 0.0], [0.0, 0.05, 0.0],
           [0.0, 0.0, 0.05], [1.0, 0.0, 0.05], [1.0, 0.05, 0.05], [0.0, 0.05, 0.05]]
nx = 5
ny = 1
nz = 1
[sets.clamp]
x = 0.0
[[bc]]
set = "clamp"
dofs = ["x", "y", "z"]
[analysis]
type = "modal"
modes = 4
[study]
kind = "modal_refinement"
refinements = [1, 2, 4]
elements = ["hex8i", "hex20"]
modes = 4
)";

class ModalRefinementStudy : public test::TempFolderTest {};

TEST_F(ModalRefinementStudy, ErrorsFallWithRefinementAndVanishOnTheFinestHex20Mesh) {
  const CaseSpec spec = parse_case_file(write(kBar));
  const ModalRefinementResult r = run_modal_refinement_study(spec.model, std::get<ModalSpec>(spec.analysis),
                                                             std::get<ModalRefinementStudySpec>(*spec.study));
  ASSERT_EQ(r.rows.size(), 6u);
  const ModalRefinementRow& ref = r.rows[static_cast<size_t>(r.reference_row)];
  EXPECT_EQ(ref.element, ElementType::hex20);
  EXPECT_EQ(ref.refinement, 4);
  EXPECT_EQ(ref.max_error, 0.0);
  for (size_t i = 1; i < r.rows.size(); ++i) {
    if (r.rows[i].element != r.rows[i - 1].element) continue;
    EXPECT_GT(r.rows[i].n_free_dofs, r.rows[i - 1].n_free_dofs);
    if (static_cast<int>(i) != r.reference_row) {
      EXPECT_LT(r.rows[i].max_error, r.rows[i - 1].max_error) << i;
    }
  }
  for (const ModalRefinementRow& row : r.rows) EXPECT_EQ(row.frequencies_hz.size(), 4u);
}

TEST_F(ModalRefinementStudy, NeedsASolidModalCase) {
  std::string text = kBar;
  text.replace(text.find("type = \"modal\"\nmodes = 4"), std::string("type = \"modal\"\nmodes = 4").size(),
               "type = \"static\"");
  EXPECT_THROW(parse_case_file(write(text)), InputError);
}

}  // namespace
}  // namespace bb
