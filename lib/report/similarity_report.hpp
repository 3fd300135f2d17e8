// The similarity report (issue #6): one document with the inputs, Table 1 and the similarity
// groups, Figs. 3 and 4 with their collapse, the bridge models' accuracy and cost, the slump study
// (pictures, profiles, errors, speed-up, best exponent, verdict), optionally the measured exponent
// (response curves and k-hat), and the caveats. Written as
// DIR/report.html (self-contained) and DIR/report.md with DIR/figures/ beside it; both appear only
// once everything is computed (temporary files renamed), so an interrupted run leaves no half report.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "io/table_config.hpp"
#include <vector>

#include "slump/response_study.hpp"

namespace demscale::report {

struct ReportOptions {
    std::string scene_path, scene_label;    // slump scene (label: as shown to the reader)
    io::TableConfig similarity;             // the similarity table's and Figs. 3-4's inputs (source: their file)
    std::string bridge_table_path;          // tabulated exact bridge (data/bridge_table.csv)
    std::vector<double> exponents;          // empty: the configuration's
    std::vector<double> scale_factors = {1.40, 1.96, 2.74, 3.84};
    bool quick = false;                     // coarse bridge grid, short cost timing
    std::filesystem::path out_dir;
    std::optional<std::filesystem::path> cache_dir;
    int jobs = 1, threads_per_job = 1;
    std::optional<slump::SlurmSettings> slurm;  // the slump runs go to Slurm (slump/slurm_backend.hpp)
    int seeds = 8;                          // runs per ensemble, fine and coarse
    unsigned seed_base = 0;                 // first seed of every ensemble (0: the scene's own)
    int liggghts_ranks = 0;                 // > 0: LIGGGHTS lifts and spreads, on this many ranks (slump/liggghts_run.hpp)
    slump::Baseline baseline = slump::Baseline::dry;  // a wet scene's dry control (slump/study.hpp)
    std::string git_revision;               // shown in the inputs
    std::function<void(const std::string&)> live;  // slump runs in progress (slump::BatchOptions::live)
    // The measured exponent (its fine scene and runner filled in by the report): none, no section.
    std::optional<slump::ResponsePlan> estimate;
};

struct ReportOutcome {
    std::filesystem::path html, markdown;
    std::vector<std::string> caveats;
    double wall_s = 0;
};

ReportOutcome write_similarity_report(const ReportOptions& o, const std::function<void(const std::string&)>& log = {});

}  // namespace demscale::report
