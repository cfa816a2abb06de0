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

double remaining_seconds(double remaining_cost, double done_cost, double elapsed_s) {
  if (!(remaining_cost > 0.0)) return 0.0;
  if (!(done_cost > 0.0) || !(elapsed_s > 0.0)) return -1.0;
  return remaining_cost * elapsed_s / done_cost;
}

std::string work_progress_text(double fraction,
                               const std::string& stage,
                               int stage_done,
                               int stage_runs,
                               double elapsed_s,
                               double left_s) {
  constexpr int kWidth = 24;
  fraction = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  const int filled = std::clamp(static_cast<int>(fraction * kWidth), 0, kWidth);
  return fmt::format("[{}{}] {:3.0f}%  {} {}/{}  elapsed {}  left {}",
                     std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(kWidth - filled), '.'), 100.0 * fraction,
                     stage, stage_done, stage_runs, format_duration(elapsed_s),
                     format_duration(left_s));
}

WorkProgress::WorkProgress(std::FILE* out, double total_cost, int terminal)
    : out_(out),
      total_(total_cost),
      terminal_(terminal < 0 ? (out != nullptr && ::isatty(::fileno(out)) != 0) : terminal != 0),
      start_(std::chrono::steady_clock::now()) {
  if (out_ == nullptr) return;
  // Redraws once a second (throttled to 10 s off a terminal) so that the times move between runs.
  ticker_ = std::jthread([this](const std::stop_token& stop) {
    std::unique_lock lock(mutex_);
    while (!stop.stop_requested()) {
      wake_.wait_for(lock, stop, std::chrono::seconds(1), [] { return false; });
      if (!stop.stop_requested()) maybe_draw_locked(false);
    }
  });
}

WorkProgress::~WorkProgress() {
  ticker_.request_stop();
  if (ticker_.joinable()) ticker_.join();
}

void WorkProgress::stage(const std::string& name,
                         int runs,
                         int runs_done,
                         double skipped_cost,
                         const std::string& line) {
  const std::lock_guard lock(mutex_);
  if (!line.empty()) print_locked(line);
  stage_ = name;
  stage_runs_ = runs;
  stage_done_ = runs_done;
  done_disk_ += skipped_cost;
  maybe_draw_locked(true);
}

void WorkProgress::done(double cost, bool ran_here) {
  const std::lock_guard lock(mutex_);
  ++stage_done_;
  (ran_here ? done_here_ : done_disk_) += cost;
  drawn_latest_ = false;
  maybe_draw_locked(false);
}

void WorkProgress::log(const std::string& line) {
  if (out_ == nullptr) return;
  const std::lock_guard lock(mutex_);
  print_locked(line);
  if (terminal_ && !finished_ && !stage_.empty()) draw_locked();
  std::fflush(out_);
}

void WorkProgress::print_locked(const std::string& line) {
  if (out_ == nullptr) return;
  if (terminal_) std::fputs("\r\033[K", out_);
  std::fprintf(out_, "%s\n", line.c_str());
}

void WorkProgress::finish() {
  ticker_.request_stop();
  if (ticker_.joinable()) ticker_.join();
  if (out_ == nullptr) return;
  const std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (stage_.empty()) return;  // nothing ran
  if (!drawn_latest_) draw_locked();
  if (terminal_) std::fputc('\n', out_);
  std::fflush(out_);
}

void WorkProgress::maybe_draw_locked(bool force) {
  if (out_ == nullptr || finished_ || stage_.empty()) return;
  const auto since = std::chrono::steady_clock::now() - last_draw_;
  const auto every = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(10000);
  if (force || since >= every) draw_locked();
}

void WorkProgress::draw_locked() {
  last_draw_ = std::chrono::steady_clock::now();
  drawn_latest_ = true;
  const double elapsed = std::chrono::duration<double>(last_draw_ - start_).count();
  const double done = done_here_ + done_disk_;
  // The same costs summed in another order may miss the total by a rounding error.
  const bool all_done = !(total_ - done > 1e-9 * total_);
  const double fraction = all_done ? 1.0 : done / total_;
  const std::string text =
      work_progress_text(fraction, stage_, stage_done_, stage_runs_, elapsed,
                         remaining_seconds(all_done ? 0.0 : total_ - done, done_here_, elapsed));
  if (terminal_) {
    std::fprintf(out_, "\r%s\033[K", text.c_str());
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
}

}  // namespace corlab::study
