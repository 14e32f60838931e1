// "for_each_method" (app/window/script/ui_script_actions.h): a lesson's actions played once per
// shadow method of the registry, so the all-methods lesson names none by hand. Its expansion
// over the program's registry gives what the lesson used to write out (the methods in order,
// each charged for the stages it needs beyond the shared G-buffer and light), and bad loops
// are refused before the window opens.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/pipeline.h"
#include "window/script/ui_script.h"
#include "window/script/ui_script_actions.h"

using nlohmann::json;

namespace {

ScriptAction loopOfTheLesson() {
  std::vector<ScriptAction> actions;
  EXPECT_EQ(parseScriptFile(std::string(PENUMBRA_SOURCE_DIR) + "/lessons/all_methods.json", actions), "");
  for (const ScriptAction& action : actions)
    if (action.name == "for_each_method") return action;
  ADD_FAILURE() << "lessons/all_methods.json has no for_each_method";
  return {};
}

}  // namespace

TEST(LessonForEachMethod, TheAllMethodsLessonVisitsEveryMethodOfTheRegistry) {
  Pipeline pipeline;
  // As the lesson sets them before its loop: the thesis's N-buffer and hierarchical search.
  ASSERT_EQ(pipeline.set("trace.hierarchy=nbuffer"), "");
  ASSERT_EQ(pipeline.set("trace.search=hierarchical"), "");
  const ScriptAction loop = loopOfTheLesson();
  const auto expanded = expandForEachMethod(pipeline, loop.argument);
  std::vector<std::string> shown, captions;
  for (const auto& [name, argument] : expanded) {
    if (name == "select_output") shown.push_back(argument.get<std::string>());
    if (name == "export_view") captions.push_back(argument.value("file", "") + ": " + argument.value("caption", ""));
  }
  std::vector<std::string> outputs;
  for (const std::string& method : pipeline.methods()) outputs.push_back(pipeline.methodOutput(method));
  EXPECT_EQ(shown, outputs);
  ASSERT_EQ(captions.size(), pipeline.methods().size());
  // The charged stages the lesson once listed by hand, now derived from the graph.
  const std::pair<const char*, const char*> charged[] = {
      {"a_trace.png", "{ms:light_layers+nbuffer+classify+trace}"},
      {"b_filter.png", "{ms:light_layers+nbuffer+classify+trace+filter}"},
      {"c_hard_shadow.png", "{ms:light_layers+hard_shadow}"},
      {"d_pcss.png", "{ms:light_layers+pcss}"},
      {"e_ssm.png", "{ms:ssm}"},
      {"f_raster4d.png", "{ms:raster4d}"}};
  for (const auto& [file, ms] : charged) {
    const auto it = std::find_if(captions.begin(), captions.end(),
                                 [&](const std::string& c) { return c.rfind(std::string(file) + ": ", 0) == 0; });
    ASSERT_NE(it, captions.end()) << file;
    EXPECT_NE(it->find(ms), std::string::npos) << *it;
  }
}

TEST(LessonForEachMethod, BadLoopsAreRefusedNamingTheAction) {
  const auto problem = [](const std::string& text) {
    std::vector<ScriptAction> actions;
    return parseScriptJson(json::parse(text), actions);
  };
  EXPECT_EQ(problem(R"([{"for_each_method": [{"select_output": "{method.output}"}]}])"), "");
  EXPECT_NE(problem(R"([{"for_each_method": []}])").find("non-empty list"), std::string::npos);
  std::string message = problem(R"([{"for_each_method": [{"select_output": "{method.name}"}]}])");
  EXPECT_NE(message.find("unknown placeholder '{method.name}'"), std::string::npos) << message;
  message = problem(R"([{"for_each_method": [{"for_each_method": [{"wait": 1}]}]}])");
  EXPECT_NE(message.find("cannot be played once per method"), std::string::npos) << message;
  message = problem(R"([{"for_each_method": [{"say": "{method}"}]}])");
  EXPECT_NE(message.find("say cannot"), std::string::npos) << message;
  message = problem(R"([{"for_each_method": [{"wait": "long"}]}])");
  EXPECT_NE(message.find("action 1 of the list (wait)"), std::string::npos) << message;
  message = problem(R"([{"for_each_method": [{"nope": 1}]}])");
  EXPECT_NE(message.find("unknown action 'nope'"), std::string::npos) << message;
  // Its paths are checked as written, before the window opens.
  message = problem(R"([{"for_each_method": [{"export_view": "../{method}.png"}]}])");
  EXPECT_NE(message.find("'..'"), std::string::npos) << message;
}
