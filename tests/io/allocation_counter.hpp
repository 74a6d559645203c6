// SPDX-License-Identifier: Apache-2.0
// Counts global operator new calls in this test binary, to check that steady-state paths do not allocate.
#pragma once
#include <cstddef>

namespace rays::test {

std::size_t allocations();

}  // namespace rays::test
