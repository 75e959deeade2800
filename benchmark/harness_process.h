// Runs one measurement in a process of its own: a crash, a failure or a time-out of the measured
// method becomes a status of its own, never a crash of the harness; the child's peak memory
// is measured alone, and its time does not depend on what was measured before.

#ifndef NP_BENCHMARK_HARNESS_PROCESS_H
#define NP_BENCHMARK_HARNESS_PROCESS_H

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

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

// The measured side, in the process run_in_new_process() starts: runs `work` with the standard
// output sent to /dev/null (some measured methods print their iterations) and writes "ok", or
// "error", a tab and `work`'s payload line, or what it threw, to the standard output it was
// given. Returns the process's exit status, for std::_Exit (the measured libraries' teardown
// after the payload can then neither crash nor hold up a result).
inline int run_as_child(const std::function<std::string()>& work)
{
  const int out = dup(STDOUT_FILENO);
  if(out < 0 || std::freopen("/dev/null", "w", stdout) == nullptr) return 2;
  std::string line;
  try { line = "ok\t" + work(); }
  catch(const std::exception& e) { line = std::string("error\t") + e.what(); }
  catch(...) { line = "error\tunknown exception"; }
  line += '\n';
  return write(out, line.data(), line.size()) == ssize_t(line.size()) ? 0 : 2;
}

// Runs this program again with `arguments` (argv[1] on) in a new process, which calls
// run_as_child(), and reads its payload; waits at most `time_limit` seconds. A new program,
// not a fork: a fork inherits the harness's allocator state (glibc raises its mmap threshold
// to the size of a mapped block freed, and its trim threshold to twice that), and a small mesh
// measured after a large one ran without the page faults it has on its own, a method's time
// then depending on the meshes measured before it (doc/performance.md, "Memory").
inline Child_result run_in_new_process(const std::vector<std::string>& arguments, double time_limit)
{
  int fds[2];
  if(pipe(fds) != 0) return {"pipe failed", ""};
  std::vector<std::string> words = {"harness-child"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for(std::string& w : words) argv.push_back(&w[0]);
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if(pid < 0)
  {
    close(fds[0]);
    close(fds[1]);
    return {"fork failed", ""};
  }
  if(pid == 0)
  {
    close(fds[0]);
    if(dup2(fds[1], STDOUT_FILENO) < 0) _exit(2);
    close(fds[1]);
    execv("/proc/self/exe", argv.data());
    const char failed[] = "error\texec failed\n";
    if(write(STDOUT_FILENO, failed, sizeof failed - 1) < 0) _exit(2);
    _exit(127);
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
    if(poll(&p, 1, int((std::min)(left, 60.) * 1000) + 1) <= 0) continue; // at most a minute a wait
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
  if(tab == std::string::npos)
    return {"no result (exit status " + std::to_string(WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1) + ")", ""};
  if(output.compare(0, tab, "ok") != 0) return {output.substr(tab + 1), ""};
  return {"ok", output.substr(tab + 1)};
}

} // namespace np_benchmark

#endif
