#pragma once
// The paper's five built-in tasks, for the tests that go through each of them.
#include <string>
#include <vector>

namespace pmdplan::test {

inline const std::vector<std::string> kPaperTasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf",
                                                     "t_in_clutter"};

}  // namespace pmdplan::test
