// The work and memory an analysis will ask for, estimated from its spec and its model before it
// runs (common/work_limits.hpp bounds them). Rough counts, within a few times of the truth: what
// matters is the order of magnitude of an input that would run for hours or exhaust the memory.
#pragma once
#include "analysis/analysis_spec.hpp"
#include "common/work_limits.hpp"
#include "model/model.hpp"

namespace bb {

// The factorization of the mesh's stiffness (sparse Cholesky, nested-dissection fill): what the
// static, modal, FRF and reduction solves of a mesh cost at least. Zero for an empty mesh.
// `factors_out_of_core`: MUMPS keeps the factors on disk (ModalOptions::out_of_core), and only
// the share of them it works on at once counts in memory.
WorkEstimate estimate_mesh_work(const Model& model, bool factors_out_of_core = false);

// The analysis's own estimate (the mesh's, plus sweeps, steps, harmonics and samples); the
// larger of memory and operations decide. A rotating analysis bounds its steps itself, once its
// time step is known (rotating_analysis.cpp).
WorkEstimate estimate_work(const AnalysisSpec& spec, const Model& model);

}  // namespace bb
