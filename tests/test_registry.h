#pragma once
// Test registration: each test file registers its QtTest class under its unit name (the file name
// without "test_" and ".cpp"). A domain's runner (test_runner_main.cpp) runs the unit named by its
// first argument, so every file stays its own CTest entry while a domain links one executable.
#include <QObject>
#include <QtTest>
#include <memory>

namespace mx::test {

using TestFactory = std::unique_ptr<QObject> (*)();

// Registers `factory` under the unit name derived from `source_file`; returns true (for a static).
bool registerTest(const char* source_file, TestFactory factory);

}  // namespace mx::test

#define MX_REGISTER_TEST(TestClass)                                                                                 \
  namespace {                                                                                                       \
  const bool mx_registered_##TestClass =                                                                            \
      mx::test::registerTest(__FILE__, []() -> std::unique_ptr<QObject> { return std::make_unique<TestClass>(); }); \
  }
