// A linear static analysis: the model's constraints and loads say everything; the stresses are
// recovered at the nodes (assembly/stress_recovery) and, on request, kept at the integration points.
#pragma once

namespace bb {

struct StaticSpec {
  bool integration_point_stresses = false;  // also write integration_point_stresses.csv (unaveraged)
};

}  // namespace bb
