// Verdicts on a runs file (docs/verdicts.md, "From a runs file"): check-exponent's slump and spread
// criteria on runs made by any engine. The fine ensemble is the rows with S_f 1 at the scene's γ;
// each coarse ensemble the rows with that S_f at γ S_f^k (γ matched within 0.1 %); the dry control
// the rows with γ 0, paired with the wet ones seed by seed. A runs file holds no profiles, so the
// profile is not judged: the verdicts rest on slump and spread alone, and say so.
#pragma once

#include <string>
#include <vector>

#include "slump/ensemble_verdict.hpp"
#include "slump/runs_file.hpp"

namespace demscale::slump {

struct RunsVerdicts {
    std::vector<EnsembleVerdict> raw;        // per S_f (the order asked for)
    std::vector<EnsembleVerdict> corrected;  // with a dry control in the file: per entry of raw
    std::vector<EnsembleVerdict> controls;   // the dry coarse ensemble against the dry fine one
    Tolerances tolerances;
    bool has_control() const { return !corrected.empty(); }
    const std::vector<EnsembleVerdict>& deciding() const { return has_control() ? corrected : raw; }
    stats::Verdict overall() const { return family_verdict(deciding()); }
};

// scene_gamma: N/m. scale_factors: empty, every S_f > 1 in the file. baseline dry with no γ = 0 rows
// in the file: the raw comparison decides. Throws InputError (field --runs) when an asked S_f or the
// fine ensemble has no runs, or the dry control lacks a wet run's seed.
RunsVerdicts judge_runs(const std::vector<RunRow>& rows, const std::string& source, double scene_gamma, double exponent,
                        std::vector<double> scale_factors, const Tolerances& tolerances, Baseline baseline);

}  // namespace demscale::slump
