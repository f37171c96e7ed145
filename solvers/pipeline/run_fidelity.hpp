// A case run at the fidelity `run --fidelity` asks for: the cheapest level of every axis (fast),
// the finest (reference), or the cheapest combination whose estimated error meets the case's
// [fidelity] target (automatic). The climb starts from the cheapest level of every axis; at each
// combination every axis is probed one level finer, its error estimated by Richardson
// extrapolation with the order fitted to its last two differences (power_law_error; the plain
// difference at an axis's first level), and the axis with the largest estimate is refined, until
// the estimates' sum meets the target or every axis is at its finest.
#pragma once
#include <string>
#include <vector>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "results/table.hpp"

namespace bb {

struct FidelityChoice {
  CaseSpec spec;  // the case at the chosen levels
  Model model;
  AnalysisResults results;
  ResultTable frontier;  // every level tried: levels, unknowns, seconds, difference, estimated_error, chosen, failed
  double estimated_error = 0.0;       // of the chosen run: the sum over axes; NaN when unknown
  bool met = false;                   // automatic: estimated_error <= target
  std::string settings;               // "analysis.harmonics = 5, analysis.time_samples = 256"
  std::vector<std::string> failures;  // "settings: message" of every level whose solve failed
};

// Largest relative difference of `columns` between two runs' tables, rows paired by equal values
// of `key` (empty: the tables' key column): |a - b| / |b| per value (|a - b| / max |b| of the
// column where |b| is below 1e-6 of that maximum, a numerical zero; inf where either is not
// finite). Throws InputError when a column is missing or no row pairs.
double relative_difference(const ResultTable& coarse, const ResultTable& fine, const std::vector<std::string>& columns,
                           const std::string& key = {});

// Runs the case's analysis at the levels `mode` asks for (fixed is not a mode here). A level whose
// solve fails (SolverError) has an infinite difference to its neighbours, so the climb passes it.
// Throws InputError when the case has no [fidelity] or the result table lacks a column, and
// SolverError when the chosen levels failed. Every level's run uses the model cache in `cache`, when given.
FidelityChoice run_with_fidelity(const CaseSpec& spec, FidelityMode mode, const HbmProgress& progress = {},
                                 const WorkLimits& limits = {}, const ModelCacheSettings* cache = nullptr);

}  // namespace bb
