// fast-cpp-csv-parser with the project's dialect: comma separated, '#' comment lines,
// blanks trimmed, a header row naming the columns.
#pragma once
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"  // inside libfccp's error-message copy
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

namespace bb {
template <unsigned N>
using CsvReader = io::CSVReader<N, io::trim_chars<' ', '\t'>, io::no_quote_escape<','>, io::throw_on_overflow,
                                io::single_line_comment<'#'>>;
}  // namespace bb
