#include "tools/experiment/experiment_file.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "planners/planner_factory.hpp"
#include "tools/experiment/value_lists.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;

// One element being read: its attributes checked against those it may have.
class Reading {
 public:
  Reading(const tinyxml2::XMLElement& e, const Experiment& x) : e_(e), x_(x) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw ExperimentError(x_.file + ":" + std::to_string(e_.GetLineNum()) + ": " + message);
  }
  void allow(std::initializer_list<const char*> names) const {
    for (auto* a = e_.FirstAttribute(); a != nullptr; a = a->Next())
      if (std::none_of(names.begin(), names.end(), [a](const char* n) { return std::string(n) == a->Name(); }))
        fail(std::string("unknown attribute '") + a->Name() + "' on <" + e_.Name() + ">");
  }
  std::string text(const char* name) const {
    const char* value = e_.Attribute(name);
    if (value == nullptr) fail(std::string("<") + e_.Name() + "> needs attribute '" + name + "'");
    if (words(value).empty()) fail(std::string("attribute '") + name + "' of <" + e_.Name() + "> is empty");
    return value;
  }
  int64_t integer(const char* name, int64_t least) const {
    const auto value = parseInteger(text(name));
    if (!value || *value < least)
      fail(std::string("attribute '") + name + "' of <" + e_.Name() + "> must be an integer >= " +
           std::to_string(least) + ", not '" + e_.Attribute(name) + "'");
    return *value;
  }
  std::string file(const char* name) const {  // an existing file, made absolute
    const fs::path path = fs::path(x_.base_dir) / text(name);
    if (!fs::is_regular_file(path)) fail("no such file: " + text(name));
    return fs::absolute(path).lexically_normal().string();
  }
  const tinyxml2::XMLElement& element() const { return e_; }

 private:
  const tinyxml2::XMLElement& e_;
  const Experiment& x_;
};

void addScene(const Reading& r, Experiment& x, Scene scene) {
  for (const auto& other : x.scenes)
    if (other.name == scene.name) r.fail("two scenes named '" + scene.name + "'");
  x.scenes.push_back(std::move(scene));
}

void readScenario(const Reading& r, Experiment& x) {
  r.allow({"file"});
  const std::string file = r.file("file");
  addScene(r, x, {fs::path(file).stem().string(), file, std::nullopt});
}

void readGenerated(const Reading& r, Experiment& x) {
  r.allow({"kind", "size", "objects", "seeds"});
  if (r.text("kind") != "district") r.fail("kind must be 'district', not '" + r.text("kind") + "'");
  const auto size = words(r.text("size"));
  const auto width = size.size() == 2 ? parseInteger(size[0]) : std::nullopt;
  const auto height = size.size() == 2 ? parseInteger(size[1]) : std::nullopt;
  if (!width || !height || *width <= 0 || *height <= 0)
    r.fail("size must be two positive integers (width height in m), not '" + r.text("size") + "'");
  const auto seeds = parseSeedList(r.text("seeds"));
  if (!seeds) r.fail("seeds must be seeds and ranges such as '1-20 25', not '" + r.text("seeds") + "'");
  Generation g{"district", static_cast<int>(*width), static_cast<int>(*height),
               static_cast<int>(r.integer("objects", 1)), 0};
  for (const uint64_t seed : *seeds) {
    g.seed = seed;
    const std::string name = g.kind + "-" + std::to_string(g.width) + "x" + std::to_string(g.height) + "-o" +
                             std::to_string(g.objects) + "-s" + std::to_string(seed);
    addScene(r, x, {name, "", g});
  }
}

void addValues(const Reading& r, Experiment& x, const std::string& factor, const std::vector<std::string>& values) {
  auto it = std::find_if(x.factors.begin(), x.factors.end(), [&](const Factor& f) { return f.name == factor; });
  if (it == x.factors.end()) it = x.factors.insert(x.factors.end(), Factor{factor, {}});
  for (const auto& value : values) {
    if (std::find(it->values.begin(), it->values.end(), value) != it->values.end())
      r.fail("'" + value + "' is twice a value of " + factor);
    it->values.push_back(value);
  }
}

void readSeeds(const Reading& r, Experiment& x) {
  r.allow({"values"});
  const auto seeds = parseSeedList(r.text("values"));
  if (!seeds) r.fail("values must be seeds and ranges such as '1-20 25', not '" + r.text("values") + "'");
  std::vector<std::string> values;
  for (const uint64_t seed : *seeds) values.push_back(std::to_string(seed));
  addValues(r, x, kSeed, values);
}

// The names beft-run's --planner takes (planners/planner_factory.hpp).
std::set<std::string> knownPlanners() {
  const auto names = planners::plannerNames();
  return {names.begin(), names.end()};
}

void readWords(const Reading& r, Experiment& x, const std::string& factor, const std::set<std::string>& allowed) {
  r.allow({"values"});
  const auto values = words(r.text("values"));
  for (const auto& value : values)
    if (!allowed.empty() && allowed.count(value) == 0) r.fail("'" + value + "' is not a value of " + factor);
  addValues(r, x, factor, values);
}

void readNets(const Reading& r, Experiment& x) {
  r.allow({"values"});
  const auto values = words(r.text("values"));
  for (const auto& value : values)
    if (!fs::is_regular_file(fs::path(x.base_dir) / value)) r.fail("no such file: " + value);
  addValues(r, x, "net", values);
}

void readSet(const Reading& r, Experiment& x) {
  r.allow({"name", "values"});
  const std::string name = r.text("name");
  if (name.find_first_of(" =") != std::string::npos) r.fail("a parameter's name has no spaces or '='");
  addValues(r, x, "set:" + name, words(r.text("values")));
}

void readCompare(const Reading& r, Experiment& x) {
  r.allow({"factor", "a", "b"});
  x.comparisons.push_back({r.text("factor"), r.text("a"), r.text("b")});
}

const Factor* factorNamed(const Experiment& x, const std::string& name) {
  for (const auto& f : x.factors)
    if (f.name == name) return &f;
  return nullptr;
}

// An <episode>'s attributes, checked once every factor is declared (resolveListed).
void readEpisode(const Reading& r, Experiment& x) {
  std::vector<std::pair<std::string, std::string>> values;
  for (auto* a = r.element().FirstAttribute(); a != nullptr; a = a->Next()) values.emplace_back(a->Name(), a->Value());
  x.listed.push_back(values);
}

// The value an <episode> gives a factor (a parameter's by its bare name).
std::string listedValue(const Reading& r, const std::vector<std::pair<std::string, std::string>>& given,
                        const Factor& factor) {
  const std::string bare = factor.name.rfind("set:", 0) == 0 ? factor.name.substr(4) : factor.name;
  for (const auto& [name, value] : given)
    if (name == bare) {
      if (std::find(factor.values.begin(), factor.values.end(), value) == factor.values.end())
        r.fail("'" + value + "' is not a value of " + factor.name);
      return value;
    }
  r.fail("<episode> gives no " + bare);
}

// Every <episode> gives each factor one of its values, and nothing else.
void resolveListed(const tinyxml2::XMLElement& root, Experiment& x) {
  std::vector<Factor> factors = {{kScene, {}}};
  for (const auto& scene : x.scenes) factors[0].values.push_back(scene.name);
  factors.insert(factors.end(), x.factors.begin(), x.factors.end());
  auto element = root.FirstChildElement("episode");
  for (auto& given : x.listed) {
    const Reading r(*element, x);
    element = element->NextSiblingElement("episode");
    for (const auto& [name, value] : given)
      if (!factorNamed(x, name) && !factorNamed(x, "set:" + name) && name != kScene)
        r.fail("unknown attribute '" + name + "' on <episode> (not a factor of the experiment)");
    std::vector<std::pair<std::string, std::string>> values;
    for (const auto& factor : factors) values.emplace_back(factor.name, listedValue(r, given, factor));
    given = values;
  }
}

void readRoot(const Reading& r, Experiment& x) {
  r.allow({"name", "max_ticks"});
  x.name = r.element().Attribute("name") ? r.text("name") : fs::path(x.file).stem().string();
  if (r.element().Attribute("max_ticks")) x.max_ticks = r.integer("max_ticks", 1);
}

void readChild(const Reading& r, Experiment& x) {
  static const std::map<std::string, std::function<void(const Reading&, Experiment&)>> readers = {
      {"scenario", readScenario},
      {"generated", readGenerated},
      {"seeds", readSeeds},
      {"planners", [](const Reading& r, Experiment& x) { readWords(r, x, "planner", knownPlanners()); }},
      {"acoustics", [](const Reading& r, Experiment& x) { readWords(r, x, "acoustics", {"ground_truth", "binaural"}); }},
      {"nets", readNets},
      {"set", readSet},
      {"compare", readCompare},
      {"episode", readEpisode}};
  const auto it = readers.find(r.element().Name());
  if (it == readers.end())
    r.fail(std::string("unknown element <") + r.element().Name() +
           "> (expected scenario, generated, seeds, planners, acoustics, nets, set, compare or episode)");
  it->second(r, x);
}

// Every <compare> names a declared factor (a parameter's by its bare name)
// other than the seed, and two of its values.
void checkComparisons(const tinyxml2::XMLElement& root, Experiment& x) {
  auto compare = root.FirstChildElement("compare");
  for (auto& c : x.comparisons) {
    const Reading r(*compare, x);
    compare = compare->NextSiblingElement("compare");
    if (c.factor == kSeed) r.fail("episodes are paired by scene and seed: compare other factors");
    if (!factorNamed(x, c.factor) && factorNamed(x, "set:" + c.factor)) c.factor = "set:" + c.factor;
    const Factor* f = factorNamed(x, c.factor);
    if (f == nullptr) r.fail("no factor '" + c.factor + "' to compare over");
    for (const auto& value : {c.a, c.b})
      if (std::find(f->values.begin(), f->values.end(), value) == f->values.end())
        r.fail("'" + value + "' is not a value of " + c.factor);
    if (c.a == c.b) r.fail("a condition compared with itself");
  }
}

}  // namespace

Experiment readExperiment(const std::string& path) {
  Experiment x;
  x.file = path;
  x.base_dir = fs::absolute(path).parent_path().string();
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS)
    throw ExperimentError(path + ":" + std::to_string(doc.ErrorLineNum()) + ": cannot read the experiment file: " +
                          (doc.ErrorStr() ? doc.ErrorStr() : "?"));
  const auto* root = doc.RootElement();
  if (root == nullptr || std::string(root->Name()) != "experiment")
    throw ExperimentError(path + ":" + std::to_string(root ? root->GetLineNum() : 1) +
                          ": the root element must be <experiment>");
  readRoot(Reading(*root, x), x);
  for (auto* e = root->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) readChild(Reading(*e, x), x);
  if (x.scenes.empty()) Reading(*root, x).fail("no scene: give <scenario file=...> or <generated ...>");
  checkComparisons(*root, x);
  resolveListed(*root, x);
  return x;
}

}  // namespace beft::experiment
