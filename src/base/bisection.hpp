// The largest fraction of a move that keeps a condition, by bisection (the corrections of the
// curving, docs/curving.md): the condition holds at 0 (where the move starts) and fails at 1.
#pragma once

namespace hocav {

// The largest fraction found in `steps` halvings of [0, 1] at which `holds(fraction)` is true
// (resolution 2^-steps; 0 when every tried fraction fails). `holds` may change state: the caller
// sets the answer's state afterwards.
template <class Holds>
double largest_fraction_holding(int steps, Holds&& holds) {
  double good = 0, bad = 1;
  for (int step = 0; step < steps; ++step) {
    const double middle = 0.5 * (good + bad);
    (holds(middle) ? good : bad) = middle;
  }
  return good;
}

}  // namespace hocav
