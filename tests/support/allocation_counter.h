#pragma once
// Heap allocations counted by replacing the global operator new: link
// tests/support/allocation_counter.cpp into a test program of its own (the replacement is
// program-wide) and compare the count before and after the code that must not allocate.

namespace icacam::test {

// Calls of any operator new in this program so far.
long allocationCount();

} // namespace icacam::test
