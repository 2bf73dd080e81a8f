#include "resharp/pipeline/option_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace resharp {
namespace {

/// Where an entry's field lives in `options`.
const void* address(const OptionInfo& info, RestoreOptions& options) {
    return std::visit([&](const auto& f) -> const void* { return &f.field(options); }, info.field);
}

/// Whether an entry's field differs between two option sets.
bool differs(const OptionInfo& info, RestoreOptions& a, RestoreOptions& b) {
    return std::visit([&](const auto& f) { return f.field(a) != f.field(b); }, info.field);
}

TEST(OptionTable, NamesAreDistinctLowerCaseFlags) {
    std::set<std::string_view> names;
    for (const OptionInfo& info : restore_option_table()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(std::string(info.name).find_first_not_of("abcdefghijklmnopqrstuvwxyz-"),
                  std::string::npos)
            << info.name;
        EXPECT_NE(info.name.front(), '-') << info.name;
        EXPECT_FALSE(info.help.empty()) << info.name;
        EXPECT_NE(info.help.back(), '.') << info.name;  // the CLI's style; Python adds one
    }
    EXPECT_FALSE(names.contains(kPaperOptionName));
}

TEST(OptionTable, EveryEntrySetsAFieldOfItsOwn) {
    RestoreOptions options;
    std::set<const void*> fields;
    for (const OptionInfo& info : restore_option_table()) {
        EXPECT_TRUE(fields.insert(address(info, options)).second) << info.name;
    }
}

// The options that --paper excludes are exactly the fields paper_variant() changes.
TEST(OptionTable, PaperChoicesAreTheFieldsPaperVariantSets) {
    RestoreOptions ours;
    RestoreOptions paper = paper_variant(ours);
    std::size_t choices = 0;
    for (const OptionInfo& info : restore_option_table()) {
        EXPECT_EQ(info.paper_choice, differs(info, ours, paper)) << info.name;
        choices += info.paper_choice;
    }
    EXPECT_EQ(choices, 8u);  // with the placement (eq. 5.2 / 5.3 in the paper)
}

TEST(OptionTable, FlagsDefaultToTheValueNotGiven) {
    RestoreOptions defaults;
    for (const OptionInfo& info : restore_option_table()) {
        if (const auto* flag = std::get_if<FlagField>(&info.field)) {
            EXPECT_NE(flag->field(defaults), flag->when_given) << info.name;
        }
    }
}

TEST(OptionTable, ChoicesNameEveryValueOnceAndTheDefault) {
    RestoreOptions defaults;
    for (const OptionInfo& info : restore_option_table()) {
        std::visit(
            [&](const auto& f) {
                if constexpr (requires { f.choices; }) {
                    std::set<std::string_view> names;
                    for (const auto& choice : f.choices) names.insert(choice.first);
                    EXPECT_EQ(names.size(), f.choices.size()) << info.name;
                    EXPECT_FALSE(choice_name(f, f.field(defaults)).empty()) << info.name;
                }
            },
            info.field);
    }
}

}  // namespace
}  // namespace resharp
