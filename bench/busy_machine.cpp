// SPDX-License-Identifier: GPL-2.0-or-later
// The library's defaults on a machine whose cores are busy with other processes. For each
// workload, size and load, the wall time of the whole call with the default settings (no
// set_threads: the grid's default thread count) and of the same call on one thread, under
// the same load, and their ratio default / one thread (below 1: the default is faster).
//
// Each call is timed from before its grid is made to its end, so that FFT planning counts,
// and each runs in a fresh process (this program run again as `--one WORKLOAD N THREADS`,
// which prints its seconds): FFTW keeps what it learnt while planning for the rest of a
// process, and a second call in the same process would plan nothing. The workloads, on the
// surface of bench/scaling_scene.hpp on an N x N grid of unit pixels:
//   pk                       the scaling scene's pk solve, K iterations from rest;
//   bugnicourt_gap_adhesive  bugnicourt on the gap, with exponential adhesion (work 0.01 E*
//                            pixel, range 0.25 pixel: a cohesive zone (pi/4) E* range^2 / work
//                            of 4.9 pixels) under mean-gap control (the gap formulation
//                            takes mean-gap or penetration control, not mean pressure), at a
//                            mean gap of a tenth of the height range (16 to 18 % contact
//                            once converged, at 256^2 to 1024^2), K iterations from rest;
//   lbfgs_fourier            the scaling scene's lbfgs_fourier solve, K iterations from rest;
//   surface                  the surface generator's call alone;
//   info                     the command `asperity info` (--no-plots, its files in a temporary
//                            directory) on an .npy file of the surface written beforehand; on
//                            one thread through ASPERITY_NUM_THREADS=1 and OMP_NUM_THREADS=1.
// Under a load of L processes per core, L x (cores online) processes spin on arithmetic
// beside the measurements (each ends by itself after 30 minutes at the latest, or when this
// program ends). Each setting is measured R times, the default and one thread in turn so
// that a drift of the load touches both alike, and the least time kept. A second table gives
// the solves' time per iteration after the first, from the solve's own clock (its progress
// callback), which leaves out the setup and the FFT planning that dominate short calls.
// Progress goes to standard error, the Markdown tables to standard output; a measurement that fails (its
// message on standard error) shows as "failed". SIGINT, SIGTERM or SIGHUP stops the program
// after the measurement under way, with the table of what was measured.
//
// usage: asperity_busy_machine [--size N]... [--workload NAME]... [--loads LIST]
//                              [--iterations K] [--repeats R] [--command PATH]
//        (defaults: 512 and 2048; every workload; loads 0,1,4 processes per core; K = 50 up
//         to 512^2, 10 from 2048^2, geometric in between; the best of 3; the command
//         ../asperity beside this program's directory)
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/scaling_scene.hpp"

namespace {

const std::vector<std::string> all_workloads = {"pk", "bugnicourt_gap_adhesive", "lbfgs_fourier",
                                                "surface", "info"};

// The signal (SIGINT, SIGTERM or SIGHUP) that asked the program to stop early, 0 if none: it
// then stops the busy processes, removes its files and prints what it measured.
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void on_stop_signal(int signal) { stop_signal = signal; }

void set_stop_signals(void (*handler)(int)) {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}

// A busy process ends by itself after this long, whatever becomes of this program.
constexpr unsigned busy_bound_seconds = 30 * 60;

// The surface of bench/scaling_scene.hpp on `grid`.
asp::SelfAffineParameters scene_surface(const asp::Grid &grid) {
  asp::SelfAffineParameters p;
  p.hurst = 0.8;
  p.long_cutoff = grid.lx();
  p.rolloff = 0.25 * grid.lx();
  p.short_cutoff = 4.0;
  p.norm = asp::RoughnessNorm::rms_slope;
  p.target = 0.1;
  p.seed = 1;
  return p;
}

std::shared_ptr<asp::Grid> make_grid(std::int64_t n, bool one_thread) {
  auto grid = asp::Grid::create(2, n, n, static_cast<double>(n), static_cast<double>(n));
  if (one_thread) grid->set_threads(1);
  return grid;
}

// What one call took: in all, and per iteration after the first (0 for calls without
// iterations), from the solve's own clock as its progress callback sees it, so that setup
// and FFT planning are left out of the latter.
struct CallTimes {
  double total = 0.0;
  double per_iteration = 0.0;
};

// K iterations on the grid itself, whatever the error: the tolerance out of reach, no stall
// test, no nested grids. A solve that
// ends otherwise (a breakdown) is not the work meant, and is refused. Returns the seconds
// per iteration after the first.
double solve_fixed(asp::Solver &solver, asp::System &system, asp::Control control, double value,
                   int iterations) {
  solver.set_option("levels", 0.0);  // the grid's own iterations (the default nests grids)
  solver.set_option("tolerance", 1e-300);
  solver.set_option("stall_window", 0.0);
  solver.set_option("max_iterations", static_cast<double>(iterations));
  bench::IterationClock clock;
  clock.watch(solver);
  solver.solve(system, control, value);
  if (solver.report().termination != asp::Termination::iteration_limit)
    throw std::runtime_error(std::string("the solve ended: ") +
                             asp::termination_name(solver.report().termination));
  return clock.per_iteration(0.0);
}

// The times of one library workload, from before its grid is made.
CallTimes library_call(const std::string &workload, std::int64_t n, bool one_thread,
                       int iterations) {
  const auto start = std::chrono::steady_clock::now();
  CallTimes t;
  auto grid = make_grid(n, one_thread);
  if (workload == "surface") {
    std::vector<double> h(static_cast<std::size_t>(grid->local_pixels()));
    asp::self_affine_topography(*grid, scene_surface(*grid), h.data());
  } else if (workload == "bugnicourt_gap_adhesive") {
    bench::ScalingScene scene = bench::scaling_scene(grid, "bugnicourt");
    scene.system->set_adhesion(0.01, 0.25);
    asp::Solver solver("bugnicourt");
    solver.set_option("variable", std::string("gap"));
    t.per_iteration = solve_fixed(solver, *scene.system, asp::Control::mean_gap,
                                  0.1 * scene.system->height_range(), iterations);
  } else {
    bench::ScalingScene scene = bench::scaling_scene(grid, workload.c_str());
    asp::Solver solver(workload);
    t.per_iteration = solve_fixed(solver, *scene.system, scene.control, scene.value, iterations);
  }
  t.total = bench::seconds_since(start);
  return t;
}

// Starts `path` with `arguments` (argv[0] included), its standard output on `out_fd` (-1:
// /dev/null); returns its pid, or -1. Only calls that are safe after fork() run between fork
// and exec.
pid_t start_program(const std::string &path, const std::vector<std::string> &arguments,
                    int out_fd) {
  std::vector<char *> argv;
  for (const std::string &a : arguments) argv.push_back(const_cast<char *>(a.c_str()));
  argv.push_back(nullptr);
  const int null_fd = out_fd < 0 ? open("/dev/null", O_WRONLY | O_CLOEXEC) : -1;
  const pid_t pid = fork();
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    dup2(out_fd < 0 ? null_fd : out_fd, STDOUT_FILENO);
    execv(path.c_str(), argv.data());
    _exit(127);
  }
  if (null_fd >= 0) close(null_fd);
  return pid;
}

// The exit status of the process `pid`, or -1 if it did not exit.
int wait_for(pid_t pid) {
  int status = 0;
  if (pid < 0) return -1;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The standard output of `path` with `arguments`, and whether it exited with status 0.
bool capture(const std::string &path, const std::vector<std::string> &arguments,
             std::string &output) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return false;
  const pid_t pid = start_program(path, arguments, fds[1]);
  close(fds[1]);
  output.clear();
  char buffer[4096];
  ssize_t got;
  while ((got = read(fds[0], buffer, sizeof buffer)) != 0) {
    if (got > 0)
      output.append(buffer, static_cast<std::size_t>(got));
    else if (errno != EINTR)
      break;
  }
  close(fds[0]);
  return wait_for(pid) == 0;
}

// The command's work on the surface file of size n, timed around its whole process.
double info_call(const std::string &command, const std::string &file, bool one_thread,
                 bool no_wisdom) {
  std::vector<std::string> arguments = {command,    "info",         file,
                                        "--output", file + "-info", "--no-plots"};
  if (no_wisdom) arguments.push_back("--no-wisdom");
  if (one_thread) {
    setenv("ASPERITY_NUM_THREADS", "1", 1);
    setenv("OMP_NUM_THREADS", "1", 1);
  }
  const auto start = std::chrono::steady_clock::now();
  const int status = wait_for(start_program(command, arguments, -1));
  const double seconds = bench::seconds_since(start);
  if (status != 0)
    throw std::runtime_error(command + " info " + file + ": exit status " + std::to_string(status));
  return seconds;
}

// An .npy file (format 1.0, little-endian doubles, C order) of the n x n heights h.
void write_npy(const std::string &path, std::int64_t n, const std::vector<double> &h) {
  const std::string size = std::to_string(n);
  std::string header =
      "{'descr': '<f8', 'fortran_order': False, 'shape': (" + size + ", " + size + "), }";
  // The magic, the version and the header's length take 10 bytes; the whole is padded with
  // spaces to a multiple of 64 and ends with a newline.
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string bytes = "\x93NUMPY\x01";
  bytes += '\0';
  bytes += static_cast<char>(header.size() & 0xff);
  bytes += static_cast<char>(header.size() >> 8);
  bytes += header;
  for (double value : h) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int k = 0; k < 8; ++k) bytes += static_cast<char>((bits >> (8 * k)) & 0xff);
  }
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.good()) throw std::runtime_error("cannot write " + path);
}

std::string surface_file(const std::string &directory, std::int64_t n) {
  return directory + "/surface-" + std::to_string(n) + ".npy";
}

// Processes that spin on arithmetic until killed, until this program ends (their parent's
// death signal) or, at the latest, busy_bound_seconds after their start.
std::vector<pid_t> start_busy(int count) {
  std::vector<pid_t> pids;
  const pid_t parent = getpid();
  for (int k = 0; k < count; ++k) {
    const pid_t pid = fork();
    if (pid == 0) {
      set_stop_signals(SIG_DFL);
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(0);
      alarm(busy_bound_seconds);
      timespec now;
      clock_gettime(CLOCK_MONOTONIC, &now);
      const time_t deadline = now.tv_sec + busy_bound_seconds;
      volatile double x = 1.0;
      for (;;) {
        for (int i = 0; i < (1 << 22); ++i) x = x * 0.999999 + 1e-6;
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (now.tv_sec >= deadline || getppid() != parent) _exit(0);
      }
    }
    if (pid < 0) {
      std::perror("fork");
      break;
    }
    pids.push_back(pid);
  }
  return pids;
}

void stop_busy(std::vector<pid_t> &pids) {
  for (pid_t pid : pids) kill(pid, SIGKILL);
  for (pid_t pid : pids)
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  pids.clear();
}

int default_iterations(std::int64_t n) {
  // 50 up to 512^2 and 10 from 2048^2: a solve of a second or so on one thread.
  const double k = 50.0 * std::pow(512.0 / static_cast<double>(n), std::log(5.0) / std::log(4.0));
  return static_cast<int>(std::lround(std::clamp(k, 10.0, 50.0)));
}

// The hidden mode: one measurement, its seconds in all and per iteration on standard output.
int one_measurement(int argc, char **argv) {
  if (argc < 5) return 2;
  const std::string workload = argv[2];
  const std::int64_t n = std::atoll(argv[3]);
  const bool one_thread = std::atoi(argv[4]) == 1;
  int iterations = 0;
  std::string command, file;
  bool no_wisdom = false;
  for (int i = 5; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--iterations" && i + 1 < argc)
      iterations = std::atoi(argv[++i]);
    else if (arg == "--command" && i + 1 < argc)
      command = argv[++i];
    else if (arg == "--file" && i + 1 < argc)
      file = argv[++i];
    else if (arg == "--no-wisdom")
      no_wisdom = true;
    else
      return 2;
  }
  try {
    const CallTimes t = workload == "info"
                            ? CallTimes{info_call(command, file, one_thread, no_wisdom), 0.0}
                            : library_call(workload, n, one_thread, iterations);
    std::printf("%.9g %.9g\n", t.total, t.per_iteration);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "%s %lld on %s: %s\n", workload.c_str(), static_cast<long long>(n),
                 one_thread ? "1 thread" : "the default threads", e.what());
    return 1;
  }
  return 0;
}

struct Best {
  double defaults = -1.0, one = -1.0;  // seconds; -1: not measured, -2: failed
  double defaults_iteration = -1.0, one_iteration = -1.0;  // per iteration; -1: none
};

const char *const usage =
    "usage: %s [--size N]... [--workload NAME]... [--loads LIST] [--iterations K] "
    "[--repeats R] [--command PATH]\n"
    "  workloads: pk, bugnicourt_gap_adhesive, lbfgs_fourier, surface, info\n";

}  // namespace

int main(int argc, char **argv) {
  if (argc > 1 && std::strcmp(argv[1], "--one") == 0) return one_measurement(argc, argv);

  std::vector<std::int64_t> sizes;
  std::vector<std::string> workloads;
  std::vector<int> loads;
  int iterations = 0, repeats = 3;
  std::string command;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    bool ok = true;
    if (arg == "--size" && has_value) {
      sizes.push_back(std::atoll(argv[++i]));
      ok = sizes.back() >= 2;
    } else if (arg == "--workload" && has_value) {
      workloads.push_back(argv[++i]);
      ok = std::count(all_workloads.begin(), all_workloads.end(), workloads.back()) == 1;
    } else if (arg == "--loads" && has_value) {
      const std::string list = argv[++i];
      for (std::size_t at = 0; ok && at <= list.size();) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        const std::string item = list.substr(at, comma - at);
        ok = !item.empty() && item.find_first_not_of("0123456789") == std::string::npos;
        if (ok) loads.push_back(std::atoi(item.c_str()));
        at = comma + 1;
      }
    } else if (arg == "--iterations" && has_value) {
      iterations = std::atoi(argv[++i]);
      ok = iterations >= 1;
    } else if (arg == "--repeats" && has_value) {
      repeats = std::atoi(argv[++i]);
      ok = repeats >= 1;
    } else if (arg == "--command" && has_value) {
      command = argv[++i];
    } else {
      ok = false;
    }
    if (!ok) {
      std::fprintf(stderr, usage, argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {512, 2048};
  if (workloads.empty()) workloads = all_workloads;
  if (loads.empty()) loads = {0, 1, 4};
  const auto iterations_at = [&](std::int64_t n) {
    return iterations > 0 ? iterations : default_iterations(n);
  };
  const int cores = static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));

  set_stop_signals(on_stop_signal);

  // The command and its surfaces, made before any timing.
  const bool with_info = std::count(workloads.begin(), workloads.end(), "info") > 0;
  std::string directory;
  bool no_wisdom = false;
  if (with_info) {
    if (command.empty()) {
      char self[4096];
      const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
      if (length > 0)
        command = std::filesystem::path(std::string(self, static_cast<std::size_t>(length)))
                      .parent_path()
                      .parent_path() /
                  "asperity";
    }
    std::string help;
    if (command.empty() || access(command.c_str(), X_OK) != 0 ||
        !capture(command, {command, "info", "--help"}, help)) {
      std::fprintf(stderr, "%s: no command '%s' to run (--command PATH)\n", argv[0],
                   command.c_str());
      return 1;
    }
    no_wisdom = help.find("--no-wisdom") != std::string::npos;
    const char *tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
                          "/asperity_busy_machine.XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("mkdtemp");
      return 1;
    }
    directory = pattern;
    try {
      for (std::int64_t n : sizes) {
        auto grid = make_grid(n, true);
        std::vector<double> h(static_cast<std::size_t>(grid->local_pixels()));
        asp::self_affine_topography(*grid, scene_surface(*grid), h.data());
        write_npy(surface_file(directory, n), n, h);
      }
    } catch (const std::exception &e) {
      std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
      std::filesystem::remove_all(directory);
      return 1;
    }
  }

  std::map<std::string, std::map<std::int64_t, std::vector<Best>>> best;
  for (const std::string &workload : workloads)
    for (std::int64_t n : sizes) best[workload][n].resize(loads.size());
  bool failed = false;
  for (std::size_t level = 0; level < loads.size(); ++level) {
    const int busy = loads[level] * cores;
    std::vector<pid_t> pids = start_busy(busy);
    std::fprintf(stderr, "load %d per core: %zu busy processes\n", loads[level], pids.size());
    if (!pids.empty()) sleep(1);
    for (const std::string &workload : workloads)
      for (std::int64_t n : sizes) {
        if (stop_signal != 0) break;
        Best &b = best[workload][n][level];
        std::vector<std::string> arguments = {argv[0], "--one", workload, std::to_string(n), "0"};
        if (workload == "info") {
          arguments.insert(arguments.end(),
                           {"--command", command, "--file", surface_file(directory, n)});
          if (no_wisdom) arguments.push_back("--no-wisdom");
        } else if (workload != "surface") {
          arguments.insert(arguments.end(), {"--iterations", std::to_string(iterations_at(n))});
        }
        for (int r = 0; r < repeats && stop_signal == 0; ++r)
          for (const bool one_thread : {false, true}) {
            arguments[4] = one_thread ? "1" : "0";
            std::fprintf(stderr, "  %s %lld^2, %s, %d/%d: ", workload.c_str(),
                         static_cast<long long>(n), one_thread ? "1 thread" : "default", r + 1,
                         repeats);
            std::string output;
            double seconds = -1.0, per_iteration = 0.0;
            if (capture("/proc/self/exe", arguments, output)) {
              char *end = nullptr;
              seconds = std::strtod(output.c_str(), &end);
              per_iteration = std::strtod(end, nullptr);
            }
            double &kept = one_thread ? b.one : b.defaults;
            double &kept_iteration = one_thread ? b.one_iteration : b.defaults_iteration;
            if (seconds > 0.0) {
              std::fprintf(stderr, "%.3f s, %.4f s per iteration\n", seconds, per_iteration);
              if (kept < 0.0 || seconds < kept) kept = seconds;
              if (per_iteration > 0.0 && (kept_iteration < 0.0 || per_iteration < kept_iteration))
                kept_iteration = per_iteration;
            } else {
              std::fprintf(stderr, "failed\n");
              if (kept < 0.0) kept = -2.0;
              failed = true;
            }
          }
      }
    stop_busy(pids);
    if (stop_signal != 0) break;
  }
  if (!directory.empty()) std::filesystem::remove_all(directory);
  if (stop_signal != 0) std::fprintf(stderr, "stopped: what was measured follows\n");

  std::printf("Machine: %d cores online; a grid's default threads: %d", cores,
              asp::default_threads());
  for (const char *variable : {"OMP_NUM_THREADS", "ASPERITY_NUM_THREADS"})
    if (const char *value = std::getenv(variable)) std::printf("; %s=%s", variable, value);
  std::printf(".\nLoads (busy processes):");
  for (std::size_t level = 0; level < loads.size(); ++level)
    if (loads[level] == 0)
      std::printf("%s idle = 0", level > 0 ? "," : "");
    else
      std::printf("%s %d/core = %d", level > 0 ? "," : "", loads[level], loads[level] * cores);
  if (std::any_of(workloads.begin(), workloads.end(),
                  [](const std::string &w) { return w != "surface" && w != "info"; })) {
    std::printf(". Iterations:");
    for (std::size_t k = 0; k < sizes.size(); ++k)
      std::printf("%s %d at %lld^2", k > 0 ? "," : "", iterations_at(sizes[k]),
                  static_cast<long long>(sizes[k]));
  }
  std::printf(". Least of %d; ratio = default / 1 thread.\n", repeats);
  // One table of whole calls, then one of the time per iteration after the first (the
  // solves only), which leaves out setup and FFT planning.
  const auto table = [&](const char *title, double Best::*defaults, double Best::*one,
                         bool solves_only) {
    std::printf("\n%s\n\n| workload | N² |", title);
    for (int load : loads) {
      const std::string name = load == 0 ? "idle" : std::to_string(load) + "/core";
      std::printf(" %s: default s | %s: 1 thread s | %s: ratio |", name.c_str(), name.c_str(),
                  name.c_str());
    }
    std::printf("\n|---|---:|");
    for (std::size_t level = 0; level < loads.size(); ++level) std::printf("---:|---:|---:|");
    std::printf("\n");
    for (const std::string &workload : workloads) {
      if (solves_only && (workload == "surface" || workload == "info")) continue;
      for (std::int64_t n : sizes) {
        std::printf("| %s | %lld² |", workload.c_str(), static_cast<long long>(n));
        for (const Best &b : best[workload][n]) {
          const auto cell = [](double s) {
            if (s > 0.0)
              std::printf(" %.4g |", s);
            else
              std::printf(s < -1.5 ? " failed |" : " - |");
          };
          cell(b.*defaults);
          cell(b.*one);
          if (b.*defaults > 0.0 && b.*one > 0.0)
            std::printf(" %.2f |", b.*defaults / b.*one);
          else
            std::printf(" - |");
        }
        std::printf("\n");
      }
    }
  };
  table("Whole calls (s), FFT planning included:", &Best::defaults, &Best::one, false);
  table("Per iteration after the first (s):", &Best::defaults_iteration, &Best::one_iteration,
        true);
  std::fflush(stdout);
  if (stop_signal != 0) {
    set_stop_signals(SIG_DFL);
    raise(stop_signal);
  }
  return failed ? 1 : 0;
}
