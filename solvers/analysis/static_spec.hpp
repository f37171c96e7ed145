// A linear static analysis: the model's constraints and loads say everything.
#pragma once

namespace bb {

struct StaticSpec {};

}  // namespace bb
