// Progress of a study: called with (variants done, variants in all), with 0 before the first
// variant starts, so a terminal can show how far a long study has come and its time left.
#pragma once
#include <functional>

namespace bb {

using StudyProgress = std::function<void(int done, int total)>;

}  // namespace bb
