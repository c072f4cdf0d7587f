#pragma once
// Expect an InputError that names the file and the place (line, column, reply, key) of the problem.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan::test {

inline void expectInputError(const std::function<void()>& action, const std::string& file, const std::string& fieldPart,
                             const std::string& messagePart) {
  try {
    action();
    ADD_FAILURE() << "expected an InputError about " << fieldPart;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_THAT(e.field(), ::testing::HasSubstr(fieldPart));
    EXPECT_THAT(e.message(), ::testing::HasSubstr(messagePart));
  }
}

}  // namespace pmdplan::test
