#include "slump/slurm_backend.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/subprocess.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "slump/run_batch.hpp"
#include "slump/scene_text.hpp"

namespace demscale::slump {

namespace fs = std::filesystem;

namespace {

struct TaskId {
    std::string job;
    int index = 0;
    auto operator<=>(const TaskId&) const = default;
};

fs::path slurm_dir(const RunCache& cache) { return fs::absolute(cache.dir()) / "slurm"; }
fs::path log_of(const RunCache& cache, const TaskId& t) {
    return slurm_dir(cache) / "logs" / (t.job + "_" + std::to_string(t.index) + ".log");
}

std::string failure(const std::string& program, const CommandOutput& out) {
    if (out.exit_code == 127)
        return program + " not found: the slurm backend needs Slurm's client commands on PATH (Debian: slurm-client)";
    return program + " failed (exit " + std::to_string(out.exit_code) + "): " + out.output;
}

// Every array task in the queue, pending or running (squeue -r lists each task on its own line).
std::set<TaskId> queued_tasks() {
    const auto out = run_command({"squeue", "--noheader", "--array", "--format=%F %K"});
    if (out.exit_code != 0) throw std::runtime_error(failure("squeue", out));
    std::set<TaskId> tasks;
    std::istringstream in(out.output);
    for (std::string job, index; in >> job >> index;)
        if (index.find_first_not_of("0123456789") == std::string::npos) tasks.insert({job, std::stoi(index)});
    return tasks;
}

// The array task a run was handed to, from DIR/slurm/<key>.task ("JOB INDEX"); none: never handed.
std::optional<TaskId> task_of(const RunCache& cache, const std::string& key) {
    std::ifstream in(slurm_dir(cache) / (key + ".task"));
    TaskId t;
    if (in >> t.job >> t.index) return t;
    return std::nullopt;
}

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// The job array's script: one task per key, each running one cached run.
std::string batch_script(const std::vector<const SlurmRun*>& runs, const RunCache& cache, int threads, bool force_dt,
                         const SlurmSettings& settings) {
    const fs::path dir = slurm_dir(cache);
    std::string s = "#!/bin/bash\n";
    s += "#SBATCH --job-name=demscale\n";
    s += "#SBATCH --array=0-" + std::to_string(runs.size() - 1) + "\n";
    s += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=" + std::to_string(threads) + "\n";
    s += "#SBATCH --output=" + (dir / "logs" / "%A_%a.log").string() + "\n";
    for (const auto& o : settings.sbatch_options) s += "#SBATCH " + o + "\n";
    s += std::string("# Written by demscale ") + version + ": each task runs one slump scene (" + dir.string() +
         "/<key>.scene)\n# into the cache folder that the submitting command reads (docs/cluster.md).\n";
    s += "keys=(";
    for (const auto* r : runs) s += "\n  " + r->key;
    s += "\n)\nexport OMP_NUM_THREADS=" + std::to_string(threads) + "\n";
    s += "exec " + quoted(settings.executable.string()) + " cached-run --cache " + quoted(fs::absolute(cache.dir()).string()) +
         " --key \"${keys[$SLURM_ARRAY_TASK_ID]}\" --threads " + std::to_string(threads) + (force_dt ? " --force-dt" : "") + "\n";
    return s;
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

}  // namespace

std::string SlurmRound::summary() const {
    std::string s = "Slurm: " + std::to_string(submitted.size()) + " run(s) submitted";
    s += ", " + std::to_string(queued.size()) + " still queued from an earlier call";
    if (!lost.empty()) s += ", " + std::to_string(lost.size()) + " lost and submitted again";
    if (!jobs.empty()) s += " (job " + joined(jobs) + ")";
    return s;
}

SlurmRound submit_to_slurm(const std::vector<SlurmRun>& runs, const RunCache& cache, int threads, bool force_dt,
                           const SlurmSettings& settings, const std::function<void(const std::string&)>& log) {
    const fs::path dir = slurm_dir(cache);
    fs::create_directories(dir / "logs");
    const auto queue = queued_tasks();
    SlurmRound round;
    std::set<std::string> jobs;
    std::vector<const SlurmRun*> to_submit;
    for (const auto& r : runs) {
        if (const auto t = task_of(cache, r.key)) {
            if (queue.contains(*t)) {
                round.queued.push_back(r.key), jobs.insert(t->job);
                continue;
            }
            round.lost.push_back(r.key), round.lost_logs.push_back(log_of(cache, *t));
        }
        to_submit.push_back(&r);
    }
    if (!to_submit.empty()) {
        for (const auto* r : to_submit) io::write_file_atomically(dir / (r->key + ".scene"), scene_text(*r->scene));
        const fs::path script = dir / ("batch-" + to_submit.front()->key + "-" + std::to_string(::getpid()) + ".sh");
        io::write_file_atomically(script, batch_script(to_submit, cache, threads, force_dt, settings));
        const auto out = run_command({"sbatch", "--parsable", script.string()});
        const std::string job = out.output.substr(0, out.output.find_first_of(";\n"));
        if (out.exit_code != 0 || job.empty() || job.find_first_not_of("0123456789") != std::string::npos)
            throw std::runtime_error(failure("sbatch", out) + " (script: " + script.string() + ")");
        for (std::size_t i = 0; i < to_submit.size(); ++i) {
            io::write_file_atomically(dir / (to_submit[i]->key + ".task"), job + " " + std::to_string(i) + "\n");
            round.submitted.push_back(to_submit[i]->key);
        }
        jobs.insert(job);
        if (log) log("submitted " + std::to_string(to_submit.size()) + " run(s) as Slurm job array " + job + " (" + script.string() + ")");
    }
    round.jobs.assign(jobs.begin(), jobs.end());
    if (log)
        for (std::size_t i = 0; i < round.lost.size(); ++i)
            log("run " + round.lost[i] + " left the queue without a result (log: " + round.lost_logs[i].string() + "); submitted again");
    return round;
}

std::vector<SlumpResult> wait_for_slurm(const std::vector<SlurmRun>& runs, const RunCache& cache, const SlurmSettings& settings,
                                        const std::function<void(const std::string&)>& log) {
    std::vector<std::optional<SlumpResult>> results(runs.size());
    std::size_t last_done = runs.size() + 1;
    for (;;) {
        // The queue first: a task that leaves it has already cached its result.
        const auto queue = queued_tasks();
        std::size_t done = 0, queued = 0;
        std::vector<std::string> lost;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            const auto& r = runs[i];
            if (!results[i]) results[i] = cache.load(r.key);
            if (results[i]) ++done;
            else if (const auto t = task_of(cache, r.key); t && queue.contains(*t)) ++queued;
            else lost.push_back(r.key + " (log: " + (t ? log_of(cache, *t).string() : std::string("none")) + ")");
        }
        if (!lost.empty())
            throw std::runtime_error(std::to_string(lost.size()) + " Slurm task(s) ended without a result: " + joined(lost) +
                                     "; run the same command again to submit them again");
        if (done != last_done && log) log("Slurm: " + std::to_string(done) + " of " + std::to_string(runs.size()) + " runs cached, " +
                                          std::to_string(queued) + " in the queue");
        last_done = done;
        if (done == runs.size()) {
            std::vector<SlumpResult> out;
            for (auto& r : results) out.push_back(std::move(*r));
            return out;
        }
        for (auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(settings.poll_s);
             std::chrono::steady_clock::now() < until;) {
            if (interrupt_requested())
                throw Interrupted("stopped waiting; the runs go on in Slurm: run the same command again to collect them", "");
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
}

void run_slurm_task(const fs::path& cache_dir, const std::string& key, int threads, bool force_dt,
                    const std::function<void(const std::string&)>& log) {
    const fs::path file = fs::absolute(cache_dir) / "slurm" / (key + ".scene");
    StudyRun run;
    run.scene = scene_from_text(io::read_input_file("--key", file.string(), "a scene text written by a slurm submission"),
                                file.string());
    if (scene_key(run.scene) != key) throw InputError("--key", key, "the key of the scene in " + file.string());
    run.label = key;
    BatchOptions batch;
    batch.threads_per_job = threads, batch.cache_dir = cache_dir, batch.force_dt = force_dt;
    batch.reference_radius_m = run.scene.radius_m;
    run_batch({&run}, batch, log);
}

}  // namespace demscale::slump
