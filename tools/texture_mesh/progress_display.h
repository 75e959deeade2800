// Shows how far the command-line tool's steps have gone, in the way that fits where the standard
// error goes. On a terminal: one line, updated in place, for a step that runs longer than the
// delay (the step with its percentage, where it can say, and the seconds so far), then its time.
// Into a file or a pipe: whole lines only (a few milestones of a step that runs longer than the
// delay, and the time every step took), so that a log reads well. Quiet: nothing.
// The delay is a second, or NP_PROGRESS_DELAY seconds (0: every step is shown from its start;
// a huge value: none), which also lets a test make the display independent of the machine's
// speed.

#ifndef NP_EXAMPLES_PROGRESS_DISPLAY_H
#define NP_EXAMPLES_PROGRESS_DISPLAY_H

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace np_examples {

class Progress_display
{
public:
  enum Mode { QUIET, TERMINAL, LOG };

  // The mode for the standard error as it is now.
  static Mode mode_for_stderr(bool quiet)
  {
#ifdef _WIN32
    const bool terminal = _isatty(_fileno(stderr)) != 0;
#else
    const bool terminal = isatty(fileno(stderr)) != 0;
#endif
    return quiet ? QUIET : terminal ? TERMINAL : LOG;
  }

  // The seconds a step runs before it is shown: NP_PROGRESS_DELAY if it is a number >= 0
  // (inf: never), else 1.
  static double delay_from_environment()
  {
    const char* text = std::getenv("NP_PROGRESS_DELAY");
    if(text == nullptr)
      return 1;
    char* end = nullptr;
    const double delay = std::strtod(text, &end);
    return end != text && *end == '\0' && delay >= 0 ? delay : 1;
  }

  // Shows the steps on `out` (the standard error's buffer, taken before anything redirects it),
  // each once it has run `delay` seconds.
  Progress_display(Mode mode, std::streambuf* out, double delay = 1) : m_mode(mode), m_out(out), m_delay(delay) {}

  // The share of the running step done, in [0, 1]; may be called from any thread.
  void set_fraction(double fraction) { m_fraction.store(fraction); }

  // Runs `work` on a thread of its own while `step` is shown; returns what `work` returns.
  template <typename Work>
  auto run(const std::string& step, Work work)
  {
    m_fraction.store(-1); // unknown until the work says
    m_shown.clear();
    m_next_milestone = 25;
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    auto result = std::async(std::launch::async, work);
    for(;;)
    {
      const double elapsed = seconds();
      if(elapsed >= m_delay)
        show(step, elapsed);
      if(result.wait_for(std::chrono::milliseconds(100)) == std::future_status::ready)
        break;
    }
    finish(step, seconds());
    return result.get();
  }

private:
  static std::string duration(double seconds)
  {
    std::ostringstream text;
    text << std::fixed << std::setprecision(seconds < 1 ? 2 : 1) << seconds << " s";
    return text.str();
  }

  // The step under way, once it has run the delay.
  void show(const std::string& step, double seconds)
  {
    const double fraction = m_fraction.load();
    if(m_mode == LOG)
    {
      int passed = 0; // the last of 25%, 50% and 75% reached (100% is said by the step's time)
      while(passed < 75 && 100 * fraction >= passed + 25)
        passed += 25;
      if(passed >= m_next_milestone)
      {
        m_out << step << ": " << passed << "%\n" << std::flush;
        m_next_milestone = passed + 25;
      }
      return;
    }
    if(m_mode != TERMINAL)
      return;
    // The elapsed time rather than an estimate of the time left: the share done is itself an
    // estimate, which jumps (a solve's convergence is not linear).
    std::ostringstream text;
    text << step << ": ";
    if(fraction >= 0)
      text << std::lround(100 * fraction) << "%, ";
    text << std::lround(seconds) << " s";
    redraw(text.str());
  }

  // The step done: its time, on the line shown so far on a terminal, on a line of its own in a log.
  void finish(const std::string& step, double seconds)
  {
    const std::string done = step + ": done in " + duration(seconds);
    if(m_mode == LOG)
      m_out << done << '\n' << std::flush;
    else if(m_mode == TERMINAL && !m_shown.empty())
    {
      redraw(done);
      m_out << '\n' << std::flush;
    }
  }

  // Writes `text` over the line shown, blanking what is left of a longer one.
  void redraw(const std::string& text)
  {
    if(text == m_shown)
      return;
    m_out << '\r' << text << std::string(m_shown.size() > text.size() ? m_shown.size() - text.size() : 0, ' ')
          << std::flush;
    m_shown = text;
  }

  const Mode m_mode;
  std::ostream m_out;
  const double m_delay;
  std::atomic<double> m_fraction{-1};
  std::string m_shown;       // on the terminal's line
  int m_next_milestone = 25; // the next percentage a log reports
};

} // namespace np_examples

#endif
