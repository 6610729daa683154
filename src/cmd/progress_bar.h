// A progress bar with ETA for the terminal. It redraws at most ten times a second, only when
// standard error is a terminal, and clears its line when done, so logs and pipes stay clean.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace quaternia {

class ProgressBar {
  public:
    ProgressBar(std::string label, bool enabled);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // Thread-compatible: callers serialise (the parallel-for does). `detail` follows the ETA,
    // e.g. "120/4096 tiles".
    void update(double fraction, const std::string& detail = "");
    void finish();

    // True if standard error is a terminal.
    static bool stderrIsTerminal();

  private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace quaternia
