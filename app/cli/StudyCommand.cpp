// `mcdda study STUDY.json --out DIR`: the runs of a parameter study (docs/study.md), each in a
// child process `mcdda run ... --out DIR/runs/run_NNNN` so that a run that crashes or is killed
// is recorded as failed and the study goes on. Started by `mpirun -n N`, rank 0 hands out runs
// as ranks finish them (a dynamic work queue) and runs its own share too; started alone, it
// runs them in turn. DIR/study.csv is rewritten after every run; rerunning the study skips the
// runs that have their result.

#include "Commands.hpp"

#include "io/AtomicFile.hpp"
#include "study/Study.hpp"
#include "study/StudyCheck.hpp"

#include <nlohmann/json.hpp>

#ifdef MCDDA_HAVE_MPI
#include <mpi.h>
#endif

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

extern char** environ;

namespace mcdda::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

enum Tag { tag_ready = 1, tag_work = 2, tag_stop = 3 };

/// Launched by mpirun (Open MPI, or a PMI-based launcher such as Slurm's srun)?
bool launched_by_mpi()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(name) != nullptr) return true;
    return false;
}

std::string signal_text(int signal)
{
    const char* name = strsignal(signal);
    return "killed by signal " + std::to_string(signal) + (name ? std::string(" (") + name + ")" : std::string());
}

/// The runs of this study that have their result from an earlier start (same overrides).
std::optional<StudyRow> finished_row(const StudyRun& run, const fs::path& folder)
{
    std::ifstream in(folder / "run.json");
    if (!in) return std::nullopt;
    try {
        const json j = json::parse(in);
        if (j.at("overrides").get<std::vector<std::string>>() != run.overrides) return std::nullopt;
        std::optional<StudyRow> row = row_from_json(j.at("row").dump());
        if (row && row->index == run.index && row_is_finished(*row)) return row;
    } catch (const json::exception&) {
    }
    return std::nullopt;
}

class Runner {
public:
    Runner(const StudyDefinition& study, std::vector<StudyRun> runs, fs::path out, int threads)
        : study_(study), runs_(std::move(runs)), out_(std::move(out)), threads_(threads) {}

    const StudyRun& run(int index) const { return runs_[static_cast<std::size_t>(index - 1)]; }
    fs::path folder(int index) const { return out_ / "runs" / run(index).folder_name(); }

    /// Starts `mcdda run` for a run in its folder (emptied first), output into its log.txt.
    pid_t start(int index) const
    {
        const fs::path dir = folder(index);
        std::error_code ec;
        fs::remove_all(dir, ec);
        fs::create_directories(dir);
        std::vector<std::string> args{"mcdda", "run", study_.model, "--out", dir.string(), "--quiet"};
        if (threads_ > 0) args.insert(args.end(), {"--threads", std::to_string(threads_)});
        for (const std::string& o : run(index).overrides) args.insert(args.end(), {"--set", o});
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t files;
        posix_spawn_file_actions_init(&files);
        const std::string log = (dir / "log.txt").string();
        posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
        posix_spawn_file_actions_addclose(&files, STDIN_FILENO);
        pid_t pid = -1;
        const int failed = posix_spawn(&pid, "/proc/self/exe", &files, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&files);
        if (failed != 0) throw std::runtime_error(std::string("cannot start a run: ") + std::strerror(failed));
        return pid;
    }

    /// The row of a run whose process ended with `status` (waitpid's); a finished run records
    /// it in its folder so that a rerun of the study skips it.
    StudyRow finish(int index, int status) const
    {
        std::string failure = "no summary.json: the run did not end";
        if (WIFSIGNALED(status)) failure = signal_text(WTERMSIG(status));
        else if (WIFEXITED(status) && WEXITSTATUS(status) == exit_model_error)
            failure = "the model has errors (see " + (folder(index) / "log.txt").string() + ")";
        StudyRow row = read_run_row(study_, run(index), folder(index).string(), failure);
        if (WIFSIGNALED(status)) {  // whatever it left, it did not end
            row.status = "failed";
            row.message = failure;
        }
        if (row_is_finished(row)) {
            const json record{{"overrides", run(index).overrides}, {"row", json::parse(row_to_json(row))}};
            // The row's message may quote the --out path in whatever bytes it has.
            write_file_atomically((folder(index) / "run.json").string(), [&](std::ostream& o) {
                o << record.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
            });
        }
        return row;
    }

    /// Runs one to its end (a worker rank's way).
    StudyRow run_to_end(int index) const
    {
        const pid_t pid = start(index);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        return finish(index, status);
    }

private:
    const StudyDefinition& study_;
    std::vector<StudyRun> runs_;
    fs::path out_;
    int threads_;
};

double children_cpu_seconds()
{
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

#ifdef MCDDA_HAVE_MPI
void send_text(const std::string& text, int to, int tag)
{
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(int from, int* tag, int* source)
{
    MPI_Status status;
    MPI_Probe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::string text(static_cast<std::size_t>(size), '\0');
    MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (tag) *tag = status.MPI_TAG;
    if (source) *source = status.MPI_SOURCE;
    return text;
}
#endif

}  // namespace

int run_study(const Request& r)
{
    int rank = 0, ranks = 1;
#ifdef MCDDA_HAVE_MPI
    const bool mpi = launched_by_mpi();
    if (mpi) {
        MPI_Init(nullptr, nullptr);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    }
    struct Finalize {
        bool on;
        ~Finalize() { if (on) MPI_Finalize(); }
    } finalize{mpi};
#else
    if (launched_by_mpi()) std::cerr << "mcdda study: this build has no MPI: every rank runs the whole study\n";
#endif
    const auto started = std::chrono::steady_clock::now();
    std::vector<Diagnostic> problems;
    const std::optional<StudyDefinition> study = read_study_file(r.model, problems);
    if (rank == 0)
        for (const Diagnostic& d : problems) std::cerr << r.model << ": " << format_diagnostic(d) << "\n";
    if (!study) return exit_model_error;
    const std::vector<StudyRun> runs = expand_study(*study);
    // The base model with the values of the runs, and the outputs: a broken model, override,
    // value or output fails here, once, before anything runs.
    const StudyCheck check = check_study(*study, runs);
    if (rank == 0) {
        for (const Diagnostic& d : check.model) std::cerr << study->model << ": " << format_diagnostic(d) << "\n";
        for (const Diagnostic& d : check.study) std::cerr << r.model << ": " << format_diagnostic(d) << "\n";
    }
    if (!check.ok) return exit_model_error;
    const int threads = study->threads_per_run > 0 ? study->threads_per_run : r.threads > 0 ? r.threads : ranks > 1 ? 1 : 0;
    const fs::path out = r.out;
    Runner runner(*study, runs, out, threads);

#ifdef MCDDA_HAVE_MPI
    if (rank > 0) {  // a worker: ask, run, answer with the row, until told to stop
        send_text(std::string(), 0, tag_ready);
        for (;;) {
            int tag = 0;
            const std::string text = receive_text(0, &tag, nullptr);
            if (tag == tag_stop) break;
            send_text(row_to_json(runner.run_to_end(std::stoi(text))), 0, tag_ready);
        }
        double cpu = children_cpu_seconds(), ignored = 0.0;
        MPI_Reduce(&cpu, &ignored, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
        return exit_ok;
    }
#endif

    // Rank 0: the queue, its own runs, the table.
    std::error_code ec;
    fs::create_directories(out / "runs", ec);
    if (ec) {
        std::cerr << "mcdda study: cannot create " << (out / "runs").string() << ": " << ec.message() << "\n";
#ifdef MCDDA_HAVE_MPI
        for (int w = 1; w < ranks; ++w) {  // each worker's first request is answered with stop
            int source = 0;
            receive_text(MPI_ANY_SOURCE, nullptr, &source);
            send_text(std::string(), source, tag_stop);
        }
        if (ranks > 1) {
            double none = 0.0, sum = 0.0;
            MPI_Reduce(&none, &sum, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
        }
#endif
        return exit_output_error;
    }
    std::map<int, StudyRow> rows;
    std::deque<int> queue;
    for (const StudyRun& run : runs) {
        if (auto row = finished_row(run, runner.folder(run.index))) rows[run.index] = *row;
        else queue.push_back(run.index);
    }
    const std::size_t skipped = rows.size();
    if (!r.quiet)
        std::cout << "study " << r.model << ": " << runs.size() << " runs"
                  << (skipped ? " (" + std::to_string(skipped) + " done before, skipped)" : std::string()) << " on "
                  << ranks << (ranks == 1 ? " process" : " MPI ranks") << " -> " << out.string() << "\n";
    auto write_table = [&] {
        std::vector<StudyRow> table;
        for (const auto& [index, row] : rows) table.push_back(row);
        const std::string csv = study_csv(*study, table);
        write_file_atomically((out / "study.csv").string(), [&](std::ostream& o) { o << csv; });
    };
    auto record = [&](const StudyRow& row, int by) {
        rows[row.index] = row;
        write_table();
        if (!r.quiet)
            std::cout << "[" << rows.size() << "/" << runs.size() << "] run " << row.index << " " << row.status
                      << (ranks > 1 ? " (rank " + std::to_string(by) + ")" : std::string())
                      << (row_is_finished(row) ? std::string() : ": " + row.message) << std::endl;
        else if (!row_is_finished(row))  // --quiet keeps errors
            std::cerr << "mcdda study: run " << row.index << " " << row.status << ": " << row.message << std::endl;
    };
    write_table();

    std::optional<std::pair<int, pid_t>> own;  // rank 0's own run
    int workers_running = ranks - 1;           // until each has been told to stop
    while (own || !queue.empty() || workers_running > 0) {
        bool busy = false;
        if (!own && !queue.empty()) {
            own = std::make_pair(queue.front(), runner.start(queue.front()));
            queue.pop_front();
            busy = true;
        }
        if (own) {
            int status = 0;
            if (waitpid(own->second, &status, WNOHANG) == own->second) {
                record(runner.finish(own->first, status), 0);
                own.reset();
                busy = true;
            }
        }
#ifdef MCDDA_HAVE_MPI
        if (workers_running > 0) {
            int waiting = 0;
            MPI_Iprobe(MPI_ANY_SOURCE, tag_ready, MPI_COMM_WORLD, &waiting, MPI_STATUS_IGNORE);
            if (waiting) {
                int source = 0;
                const std::string text = receive_text(MPI_ANY_SOURCE, nullptr, &source);
                if (!text.empty())
                    if (auto row = row_from_json(text)) record(*row, source);
                if (!queue.empty()) {
                    send_text(std::to_string(queue.front()), source, tag_work);
                    queue.pop_front();
                } else {
                    send_text(std::string(), source, tag_stop);
                    --workers_running;
                }
                busy = true;
            }
        }
#endif
        if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    double cpu = children_cpu_seconds();
#ifdef MCDDA_HAVE_MPI
    if (ranks > 1) {
        double mine = cpu;
        MPI_Reduce(&mine, &cpu, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    }
#endif
    std::map<std::string, int> by_status;
    for (const auto& [index, row] : rows) ++by_status[row.status];
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (!r.quiet) {
        std::cout << "study: " << rows.size() << " runs (";
        bool first = true;
        for (const auto& [status, count] : by_status) std::cout << (first ? "" : ", ") << count << " " << status, first = false;
        std::cout << ") in " << wall << " s wall clock, " << cpu << " s CPU in the runs of this start; "
                  << (out / "study.csv").string() << "\n";
    }
    const bool all_finished = std::all_of(rows.begin(), rows.end(), [](const auto& e) { return row_is_finished(e.second); });
    return all_finished ? exit_ok : 4;  // 4: some runs failed (docs/study.md)
}

}  // namespace mcdda::cli
