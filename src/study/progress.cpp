// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace corlab::study {

double eta_seconds(double mean_case_wall_s, int remaining, int workers) {
  if (mean_case_wall_s < 0.0 || workers <= 0) return -1.0;
  if (remaining <= 0) return 0.0;
  // Cases run in waves of `workers`; a partial wave still takes one case's time.
  const double waves = std::ceil(static_cast<double>(remaining) / workers);
  return waves * mean_case_wall_s;
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0.0)) return "--";
  const auto s = static_cast<long long>(std::llround(seconds));
  if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
  if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}

std::string progress_text(int done, int total, double elapsed_s, double eta_s, int failed) {
  constexpr int kWidth = 24;
  const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
  const int filled = std::clamp(static_cast<int>(fraction * kWidth), 0, kWidth);
  std::string text =
      fmt::format("[{}{}] {}/{} {:3.0f}%  elapsed {}  ETA {}",
                  std::string(static_cast<std::size_t>(filled), '#'),
                  std::string(static_cast<std::size_t>(kWidth - filled), '.'), done, total,
                  100.0 * fraction, format_duration(elapsed_s), format_duration(eta_s));
  if (failed > 0) text += fmt::format("  ({} failed)", failed);
  return text;
}

std::function<void(double)> fraction_progress(std::FILE* out, std::string label) {
  if (out == nullptr) return {};
  const bool terminal = ::isatty(::fileno(out)) != 0;
  const auto every = terminal ? std::chrono::milliseconds(500) : std::chrono::milliseconds(10000);
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [out, terminal, every, last, label = std::move(label)](double fraction) {
    const auto now = std::chrono::steady_clock::now();
    if (fraction < 1.0 && now - *last < every) return;
    *last = now;
    if (terminal) {
      std::fprintf(out, "\r%s: %5.1f %%", label.c_str(), 100.0 * fraction);
      if (fraction >= 1.0) std::fputc('\n', out);
    } else {
      std::fprintf(out, "%s: %5.1f %%\n", label.c_str(), 100.0 * fraction);
    }
    std::fflush(out);
  };
}

ProgressBar::ProgressBar(std::FILE* out, int total, int workers, int terminal)
    : out_(out),
      total_(total),
      workers_(std::max(1, workers)),
      terminal_(terminal < 0 ? (out != nullptr && ::isatty(::fileno(out)) != 0) : terminal != 0),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int failed, double mean_case_wall_s, bool force) {
  done_ = done;
  failed_ = failed;
  mean_wall_ = mean_case_wall_s;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (force || !drawn_ || since >= (terminal_ ? 0.2 : 5.0)) draw();
}

void ProgressBar::tick() {
  if (!terminal_) return;
  const double since =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_draw_).count();
  if (since >= 1.0) draw();
}

void ProgressBar::finish() {
  if (out_ == nullptr) return;
  draw();
  if (terminal_) std::fputc('\n', out_);
  std::fflush(out_);
}

void ProgressBar::draw() {
  if (out_ == nullptr) return;
  last_draw_ = std::chrono::steady_clock::now();
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(last_draw_ - start_).count();
  const std::string text = progress_text(
      done_, total_, elapsed, eta_seconds(mean_wall_, total_ - done_, workers_), failed_);
  if (terminal_) {
    std::fprintf(out_, "\r%s\033[K", text.c_str());
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
}

}  // namespace corlab::study
