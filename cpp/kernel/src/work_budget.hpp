// A deterministic work budget for one solve (issue 13): slow inputs fail with a clear
// InputError instead of running for minutes. Work is counted in units the solvers name
// (Gauss panels of a spiral, clothoid pieces evaluated, spans certified), not in time, so
// the same input gets the same answer on a loaded machine and under the sanitizers.
// Private to the kernel.
#pragma once
#include <string>

#include "fairsplines/errors.hpp"

namespace fairsplines::detail {

/// While a WorkBudget lives on this thread, spend() counts units against it and throws
/// InputError("<what> ran out of its work budget ...") past it. Without one, spend() is free
/// (the solvers' pieces stay usable on their own). Budgets do not nest: an inner one is
/// ignored and the outer keeps counting.
class WorkBudget {
public:
  /// `why` ends the message ("<what> ran out of its work budget (N units): <why>").
  WorkBudget(double units, std::string what,
             std::string why = "these ends need curves that turn too fast or too often for a fair blend")
      : units_(units), what_(std::move(what)), why_(std::move(why)) {
    if (current() == nullptr) current() = this;
  }
  ~WorkBudget() {
    if (current() == this) current() = nullptr;
  }
  WorkBudget(const WorkBudget&) = delete;
  WorkBudget& operator=(const WorkBudget&) = delete;

  static void spend(double units) {
    WorkBudget* b = current();
    if (b == nullptr) return;
    b->spent_ += units;
    if (!(b->spent_ <= b->units_)) {
      throw InputError(b->what_ + " ran out of its work budget (" + std::to_string(static_cast<long long>(b->units_)) +
                       " units): " + b->why_);
    }
  }

private:
  static WorkBudget*& current() {
    thread_local WorkBudget* budget = nullptr;
    return budget;
  }
  double units_, spent_ = 0.0;
  std::string what_, why_;
};

}  // namespace fairsplines::detail
