// Runs a function when a scope ends, by return or by exception: what a pass that borrows the
// renderer's state uses to put it back.
#pragma once

namespace facet {

template <class F>
struct ScopeExit {
  F f;
  ~ScopeExit() { f(); }
};
// (C++20 deduces an aggregate's arguments without it; clang before 17 does not.)
template <class F>
ScopeExit(F) -> ScopeExit<F>;

}  // namespace facet
