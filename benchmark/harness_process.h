// Runs one measurement in a child process: a crash, a failure or a time-out of the measured
// method becomes a status of its own, never a crash of the harness; the child's peak memory
// is measured alone.

#ifndef NP_BENCHMARK_HARNESS_PROCESS_H
#define NP_BENCHMARK_HARNESS_PROCESS_H

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

namespace np_benchmark {

// Peak resident set size of this process in MiB (VmHWM), since start or the last reset.
inline double peak_memory_mib()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while(status >> key)
  {
    if(key == "VmHWM:")
    {
      double kib = 0;
      status >> kib;
      return kib / 1024.;
    }
    std::getline(status, key);
  }
  return 0.;
}

// Makes the next peak_memory_mib() measure from the current resident size on.
inline void reset_peak_memory()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

struct Child_result
{
  std::string status; // "ok", or why there is no result
  std::string payload; // what the child wrote, on success
};

// Runs `work` in a child; `work` returns the payload line, or throws. Waits at most
// `time_limit` seconds.
inline Child_result run_in_child(const std::function<std::string()>& work, double time_limit)
{
  int fds[2];
  if(pipe(fds) != 0) return {"pipe failed", ""};
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if(pid < 0) return {"fork failed", ""};
  if(pid == 0)
  {
    close(fds[0]);
    // Some measured methods print their iterations; only the payload leaves the child.
    if(std::freopen("/dev/null", "w", stdout) == nullptr) _exit(2);
    std::string line;
    try { line = "ok\t" + work(); }
    catch(const std::exception& e) { line = std::string("error\t") + e.what(); }
    catch(...) { line = "error\tunknown exception"; }
    line += '\n';
    if(write(fds[1], line.data(), line.size()) < 0) _exit(2);
    _exit(0);
  }
  close(fds[1]);
  std::string output;
  const auto start = std::chrono::steady_clock::now();
  bool timed_out = false;
  for(;;)
  {
    const double left = time_limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(left <= 0) { timed_out = true; break; }
    pollfd p = {fds[0], POLLIN, 0};
    if(poll(&p, 1, int(left * 1000) + 1) <= 0) continue;
    char buffer[4096];
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if(n <= 0) break;
    output.append(buffer, std::size_t(n));
  }
  close(fds[0]);
  if(timed_out) kill(pid, SIGKILL);
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  if(timed_out) return {"timeout", ""};
  if(WIFSIGNALED(wstatus)) return {"crashed (signal " + std::to_string(WTERMSIG(wstatus)) + ")", ""};
  if(!output.empty() && output.back() == '\n') output.pop_back();
  const std::size_t tab = output.find('\t');
  if(tab == std::string::npos) return {"no result", ""};
  if(output.compare(0, tab, "ok") != 0) return {output.substr(tab + 1), ""};
  return {"ok", output.substr(tab + 1)};
}

} // namespace np_benchmark

#endif
