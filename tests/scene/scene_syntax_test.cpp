// The reader's lists of calls: each made once, at the size it ends with, so
// that the monotonic resource a parse draws them from holds no list twice.

#include "scene/reading/scene_lexer.h"
#include "scene/reading/scene_syntax.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <string>
#include <vector>

using namespace capsim::scene_file;

namespace {

// A memory resource that notes the size of everything drawn from it.
class NotingResource : public std::pmr::memory_resource {
 public:
  std::vector<std::size_t> sizes;

 private:
  void* do_allocate(std::size_t bytes, std::size_t align) override {
    sizes.push_back(bytes);
    return upstream_.allocate(bytes, align);
  }
  void do_deallocate(void*, std::size_t, std::size_t) override {}
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
  std::pmr::monotonic_buffer_resource upstream_;
};

std::vector<std::string> names(const std::pmr::vector<Call>& calls) {
  std::vector<std::string> out;
  for (const Call& c : calls) out.emplace_back(c.name);
  return out;
}

// Calls without arguments, so that every list drawn is a list of calls: the
// file's (a, b and c of its bare blocks, d, f, j), d's (e), f's (g, h and i of
// its bare block; h's body is empty), j's (k) and k's (l, m).
TEST(SceneSyntax, MakesEachListOfCallsOnceAtItsSize) {
  const std::string text =
      "a(); { b(); { c(); } } ;; d() e();\n"
      "f() { g(); h() { } ; { i(); } }\n"
      "j() k() { l(); m(); }\n";
  const Tokens tokens = tokenize(text, std::make_shared<const std::string>("t.csg"));
  NotingResource memory;
  Loc end;
  const std::pmr::vector<Call> calls = read_calls(tokens, &memory, &end);
  EXPECT_EQ(names(calls), (std::vector<std::string>{"a", "b", "c", "d", "f", "j"}));
  EXPECT_EQ(names(calls[3].children), (std::vector<std::string>{"e"}));
  EXPECT_EQ(names(calls[4].children), (std::vector<std::string>{"g", "h", "i"}));
  EXPECT_TRUE(calls[4].children[1].children.empty());
  EXPECT_EQ(names(calls[5].children), (std::vector<std::string>{"k"}));
  EXPECT_EQ(names(calls[5].children[0].children), (std::vector<std::string>{"l", "m"}));
  const std::size_t call = sizeof(Call);
  EXPECT_EQ(memory.sizes, (std::vector<std::size_t>{6 * call, 1 * call, 3 * call, 1 * call, 2 * call}));
}

// A union of many objects, as OpenSCAD exports a large scene: one list of its
// size for the union's children, none grown through smaller ones.
TEST(SceneSyntax, MakesALargeUnionsListOnce) {
  std::string text = "union() {\n";
  for (int i = 0; i < 1000; ++i) text += "  s();\n";
  text += "}\n";
  const Tokens tokens = tokenize(text, std::make_shared<const std::string>("t.csg"));
  NotingResource memory;
  Loc end;
  const std::pmr::vector<Call> calls = read_calls(tokens, &memory, &end);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0].children.size(), 1000u);
  EXPECT_EQ(memory.sizes, (std::vector<std::size_t>{sizeof(Call), 1000 * sizeof(Call)}));
}

}  // namespace
