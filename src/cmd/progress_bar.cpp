#include "cmd/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace quaternia {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

ProgressBar::~ProgressBar() {
    finish();
}

bool ProgressBar::stderrIsTerminal() {
    return isatty(STDERR_FILENO) == 1;
}

void ProgressBar::update(double fraction, const std::string& detail) {
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    if (fraction < 1 && drawn_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    drawn_ = true;
    fraction = std::clamp(fraction, 0.0, 1.0);
    constexpr int kWidth = 30;
    int filled = int(std::lround(fraction * kWidth));
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    double elapsed = std::chrono::duration<double>(now - start_).count();
    char eta[32] = "--";
    if (fraction > 0.01)
        std::snprintf(eta, sizeof eta, "%.1fs", elapsed * (1 - fraction) / fraction);
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  ETA %s  %s   ", label_.c_str(), bar.c_str(),
                 fraction * 100, eta, detail.c_str());
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!enabled_ || !drawn_) return;
    std::fprintf(stderr, "\r%*s\r", 80, "");
    std::fflush(stderr);
    drawn_ = false;
}

}  // namespace quaternia
