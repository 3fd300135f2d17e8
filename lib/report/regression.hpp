// Curve regression for CI: a freshly computed table against a committed reference CSV. First the
// `# key: value` metadata (the inputs the curves were computed from: a changed input is named before
// any value), then point by point with |computed − reference| ≤ atol + rtol·|reference|; text cells
// must match exactly.
#pragma once

#include <string>
#include <vector>

#include "io/csv_reader.hpp"

namespace demscale::report {

struct Tolerance {
    double absolute = 1e-12;
    double relative = 1e-9;
};

struct Deviation {
    std::size_t row = 0;        // 0-based data row
    int line = 0;               // line in the reference file
    std::string key;            // identifying columns, e.g. "variant=mikami1998 radius_mm=1 hhat=0.25"
    std::string column;
    std::string reference, computed;
    double absolute = 0, relative = 0;
    double excess = 0;          // |Δ| / (atol + rtol·|ref|): > 1 fails
};

// A metadata line whose value differs. Informational keys (the tool version, the input file's
// name) are reported but do not fail a comparison on their own.
struct MetadataChange {
    std::string key, reference, computed;  // "(absent)" where one side lacks the key
    bool informational = false;
};

// Per column: how many values fall outside the tolerance, the largest relative difference, where.
struct ColumnSummary {
    std::string column;
    std::size_t outside = 0;
    Deviation largest;
};

struct Comparison {
    std::vector<MetadataChange> changed_inputs;  // metadata differences, inputs first, informational last
    std::string problem;            // structural mismatch (columns, row count); empty when none
    std::size_t values_compared = 0;
    std::vector<Deviation> failures;  // worst first
    Deviation worst;                  // the largest excess, pass or fail
    std::vector<ColumnSummary> columns;  // of the failures, most failing first
    bool inputs_changed() const;
    bool passed() const { return problem.empty() && failures.empty() && !inputs_changed(); }
};

// key_columns name the columns printed to identify a row in the report.
Comparison compare_csv(const io::CsvData& reference, const io::CsvData& computed, const Tolerance& tolerance,
                       const std::vector<std::string>& key_columns);

// A readable report: changed inputs first, then the structural problem, or a per-column summary
// and the worst `max_rows` deviations as a table.
std::string describe(const Comparison& c, const std::string& name, const Tolerance& tolerance, std::size_t max_rows = 10);

}  // namespace demscale::report
