// Every file the scenario format says "must be refused" is refused, with the
// file, the line of the offending element and a message saying what is wrong.
#include <sndfile.h>

#include <gtest/gtest.h>

#include "lib/scenario/load_scenario.hpp"
#include "tests/lib/scenario/scenario_test_dir.hpp"

namespace beft::scenario {
namespace {

using testing::lineOf;

// A valid scenario around `body` (objects, paths, events...).
std::string scenarioWith(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n"
         "<scenario name=\"t\" duration=\"60\">\n"
         "  <world width=\"30\" height=\"20\"/>\n"
         "  <robot x=\"2\" y=\"2\"/>\n" +
         body +
         "\n</scenario>\n";
}

const std::string kVictim =
    "  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
    "    <visual shape=\"cylinder\" radius=\"0.3\" height=\"1.8\"/>\n"
    "    <acoustic sound=\"sounds/beep.wav\"/>\n"
    "  </object>\n";

class Refusal : public testing::ScenarioTestDir {
 protected:
  // Loads `xml` and expects a refusal at the first line containing `marker`,
  // whose message contains `what`.
  void expectRefused(const std::string& xml, const std::string& marker, const std::string& what) {
    const std::string path = write(xml);
    const int expected_line = lineOf(xml, marker);
    ASSERT_GT(expected_line, 0) << "marker '" << marker << "' is not in the test file";
    try {
      loadScenario(path, nullptr);
      ADD_FAILURE() << "accepted a file that must be refused (" << what << ")";
    } catch (const ScenarioError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_EQ(error.line(), expected_line) << error.what();
      EXPECT_NE(error.message().find(what), std::string::npos) << "message: " << error.message();
      const std::string prefix = path + ":" + std::to_string(expected_line) + ": ";
      EXPECT_EQ(std::string(error.what()).substr(0, prefix.size()), prefix);
    }
  }
};

TEST_F(Refusal, MalformedXmlUnclosedElement) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\">\n"
      "  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
      "<world", "malformed XML");
}

TEST_F(Refusal, MalformedXmlUnquotedAttribute) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=2 y=\"2\"/>\n</scenario>\n",
      "<robot", "malformed XML");
}

TEST_F(Refusal, RootElementIsNotScenario) {
  expectRefused("<?xml version=\"1.0\"?>\n<world width=\"30\" height=\"20\"/>\n", "<world",
                "the root element must be <scenario>");
}

TEST_F(Refusal, MissingFileIsRefusedWithoutLine) {
  const std::string path = (dir_ / "absent.xml").string();
  try {
    loadScenario(path, nullptr);
    ADD_FAILURE() << "accepted a missing file";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_NE(error.message().find("cannot open"), std::string::npos) << error.message();
  }
}

TEST_F(Refusal, MissingWorldElement) {
  expectRefused("<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
                "<scenario", "missing required element <world>");
}

TEST_F(Refusal, MissingRobotElement) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n</scenario>\n",
      "<scenario", "missing required element <robot>");
}

TEST_F(Refusal, SecondWorldElement) {
  expectRefused(scenarioWith("  <world width=\"10\" height=\"10\"/>"), "<world width=\"10\"",
                "<world> may appear only once");
}

// --- each missing required attribute ---

struct MissingAttributeCase {
  const char* name;
  std::string xml;
  const char* marker;
  const char* what;
};

class MissingAttribute : public Refusal, public ::testing::WithParamInterface<MissingAttributeCase> {};

TEST_P(MissingAttribute, IsRefusedAtItsElement) {
  expectRefused(GetParam().xml, GetParam().marker, GetParam().what);
}

const std::string kObjectA = "  <object id=\"a\" label=\"person\" x=\"5\" y=\"5\"/>\n";

INSTANTIATE_TEST_SUITE_P(
    Scenario, MissingAttribute,
    ::testing::Values(
        MissingAttributeCase{"ScenarioName",
                             "<?xml version=\"1.0\"?>\n<scenario duration=\"60\">\n"
                             "  <world width=\"30\" height=\"20\"/>\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
                             "<scenario", "<scenario> is missing required attribute 'name'"},
        MissingAttributeCase{"WorldWidth",
                             "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n"
                             "  <world height=\"20\"/>\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
                             "<world", "<world> is missing required attribute 'width'"},
        MissingAttributeCase{"WorldHeight",
                             "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n"
                             "  <world width=\"30\"/>\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
                             "<world", "<world> is missing required attribute 'height'"},
        MissingAttributeCase{"RobotX",
                             "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n"
                             "  <world width=\"30\" height=\"20\"/>\n  <robot y=\"2\"/>\n</scenario>\n",
                             "<robot", "<robot> is missing required attribute 'x'"},
        MissingAttributeCase{"RobotY",
                             "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n"
                             "  <world width=\"30\" height=\"20\"/>\n  <robot x=\"2\"/>\n</scenario>\n",
                             "<robot", "<robot> is missing required attribute 'y'"},
        MissingAttributeCase{"ObjectId", scenarioWith("  <object label=\"person\" x=\"5\" y=\"5\"/>"),
                             "<object", "<object> is missing required attribute 'id'"},
        MissingAttributeCase{"ObjectLabel", scenarioWith("  <object id=\"a\" x=\"5\" y=\"5\"/>"), "<object",
                             "<object> is missing required attribute 'label'"},
        MissingAttributeCase{"ObjectX", scenarioWith("  <object id=\"a\" label=\"person\" y=\"5\"/>"),
                             "<object", "<object> is missing required attribute 'x'"},
        MissingAttributeCase{"ObjectY", scenarioWith("  <object id=\"a\" label=\"person\" x=\"5\"/>"),
                             "<object", "<object> is missing required attribute 'y'"},
        MissingAttributeCase{"VisualShape",
                             scenarioWith("  <object id=\"a\" label=\"wall\" x=\"5\" y=\"5\">\n"
                                          "    <visual size=\"1 1 1\"/>\n  </object>"),
                             "<visual", "<visual> is missing required attribute 'shape'"},
        MissingAttributeCase{"BoxSize",
                             scenarioWith("  <object id=\"a\" label=\"wall\" x=\"5\" y=\"5\">\n"
                                          "    <visual shape=\"box\"/>\n  </object>"),
                             "<visual", "<visual> is missing required attribute 'size'"},
        MissingAttributeCase{"CylinderRadius",
                             scenarioWith("  <object id=\"a\" label=\"person\" x=\"5\" y=\"5\">\n"
                                          "    <visual shape=\"cylinder\" height=\"1.8\"/>\n  </object>"),
                             "<visual", "<visual> is missing required attribute 'radius'"},
        MissingAttributeCase{"CylinderHeight",
                             scenarioWith("  <object id=\"a\" label=\"person\" x=\"5\" y=\"5\">\n"
                                          "    <visual shape=\"cylinder\" radius=\"0.3\"/>\n  </object>"),
                             "<visual", "<visual> is missing required attribute 'height'"},
        MissingAttributeCase{"AcousticSound",
                             scenarioWith("  <object id=\"a\" label=\"person\" x=\"5\" y=\"5\">\n"
                                          "    <acoustic active=\"1\"/>\n  </object>"),
                             "<acoustic", "<acoustic> is missing required attribute 'sound'"},
        MissingAttributeCase{"PathObject",
                             scenarioWith(kObjectA + "  <path speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                                     "    <waypoint x=\"3\" y=\"1\"/>\n  </path>"),
                             "<path", "<path> is missing required attribute 'object'"},
        MissingAttributeCase{"PathSpeed",
                             scenarioWith(kObjectA + "  <path object=\"a\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                                     "    <waypoint x=\"3\" y=\"1\"/>\n  </path>"),
                             "<path", "<path> is missing required attribute 'speed'"},
        MissingAttributeCase{"WaypointX",
                             scenarioWith(kObjectA + "  <path object=\"a\" speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                                     "    <waypoint y=\"1\"/>\n  </path>"),
                             "<waypoint y=", "<waypoint> is missing required attribute 'x'"},
        MissingAttributeCase{"WaypointY",
                             scenarioWith(kObjectA + "  <path object=\"a\" speed=\"1\">\n    <waypoint x=\"1\"/>\n"
                                                     "    <waypoint x=\"3\" y=\"1\"/>\n  </path>"),
                             "<waypoint x=\"1\"/>", "<waypoint> is missing required attribute 'y'"},
        MissingAttributeCase{"EventTime",
                             scenarioWith(kObjectA + "  <events>\n    <event object=\"a\" activity=\"idle\"/>\n  </events>"),
                             "<event ", "<event> is missing required attribute 't'"},
        MissingAttributeCase{"EventObject",
                             scenarioWith(kObjectA + "  <events>\n    <event t=\"1\" activity=\"idle\"/>\n  </events>"),
                             "<event ", "<event> is missing required attribute 'object'"},
        MissingAttributeCase{"CongruencyLabel",
                             scenarioWith("  <congruency>\n    <c activity=\"idle\" value=\"0.5\"/>\n  </congruency>"),
                             "<c ", "<c> is missing required attribute 'label'"},
        MissingAttributeCase{"CongruencyActivity",
                             scenarioWith("  <congruency>\n    <c label=\"car\" value=\"0.5\"/>\n  </congruency>"),
                             "<c ", "<c> is missing required attribute 'activity'"},
        MissingAttributeCase{"CongruencyValue",
                             scenarioWith("  <congruency>\n    <c label=\"car\" activity=\"idle\"/>\n  </congruency>"),
                             "<c ", "<c> is missing required attribute 'value'"}),
    [](const ::testing::TestParamInfo<MissingAttributeCase>& info) { return info.param.name; });

// --- numbers ---

TEST_F(Refusal, NumberThatDoesNotParse) {
  expectRefused(scenarioWith("  <object id=\"a\" label=\"person\" x=\"12abc\" y=\"5\"/>"), "<object",
                "attribute 'x' of <object> is not a number: '12abc'");
}

TEST_F(Refusal, EmptyNumber) {
  expectRefused(scenarioWith("  <object id=\"a\" label=\"person\" x=\"\" y=\"5\"/>"), "<object",
                "attribute 'x' of <object> is empty");
}

TEST_F(Refusal, NotANumber) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"nan\" height=\"20\"/>\n"
      "  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
      "<world", "attribute 'width' of <world> must be a finite number, got 'nan'");
}

TEST_F(Refusal, InfiniteNumber) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"2\" y=\"-inf\"/>\n</scenario>\n",
      "<robot", "attribute 'y' of <robot> must be a finite number, got '-inf'");
}

TEST_F(Refusal, SeedThatIsNotAnInteger) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\" seed=\"-3\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"2\" y=\"2\"/>\n</scenario>\n",
      "<scenario", "attribute 'seed' of <scenario> is not a non-negative integer");
}

// --- sizes, radii, heights, speeds, widths, resolutions that are zero or negative ---

struct NonPositiveCase {
  const char* name;
  std::string xml;
  const char* marker;
  const char* what;
};

class NonPositive : public Refusal, public ::testing::WithParamInterface<NonPositiveCase> {};

TEST_P(NonPositive, IsRefusedAtItsElement) { expectRefused(GetParam().xml, GetParam().marker, GetParam().what); }

std::string withWorld(const std::string& world_attributes) {
  return "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world " + world_attributes +
         "/>\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n";
}

std::string withHeader(const std::string& scenario_attributes) {
  return "<?xml version=\"1.0\"?>\n<scenario name=\"t\" " + scenario_attributes +
         ">\n  <world width=\"30\" height=\"20\"/>\n  <robot x=\"2\" y=\"2\"/>\n</scenario>\n";
}

std::string withRobotChild(const std::string& child) {
  return "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
         "  <robot x=\"2\" y=\"2\">\n    " + child + "\n  </robot>\n</scenario>\n";
}

std::string withVisual(const std::string& visual_attributes) {
  return scenarioWith("  <object id=\"a\" label=\"wall\" x=\"5\" y=\"5\">\n    <visual " + visual_attributes +
                      "/>\n  </object>");
}

std::string withPathSpeed(const std::string& speed) {
  return scenarioWith(kObjectA + "  <path object=\"a\" speed=\"" + speed +
                      "\">\n    <waypoint x=\"1\" y=\"1\"/>\n    <waypoint x=\"3\" y=\"1\"/>\n  </path>");
}

INSTANTIATE_TEST_SUITE_P(
    Scenario, NonPositive,
    ::testing::Values(
        NonPositiveCase{"WorldWidthZero", withWorld("width=\"0\" height=\"20\""), "<world",
                        "attribute 'width' of <world> must be > 0, got 0"},
        NonPositiveCase{"WorldHeightNegative", withWorld("width=\"30\" height=\"-20\""), "<world",
                        "attribute 'height' of <world> must be > 0, got -20"},
        NonPositiveCase{"ResolutionZero", withWorld("width=\"30\" height=\"20\" resolution=\"0\""), "<world",
                        "attribute 'resolution' of <world> must be > 0, got 0"},
        NonPositiveCase{"BoxSizeZero", withVisual("shape=\"box\" size=\"1 0 2\""), "<visual",
                        "every box size must be > 0, got '1 0 2'"},
        NonPositiveCase{"BoxSizeNegative", withVisual("shape=\"box\" size=\"-1 1 2\""), "<visual",
                        "every box size must be > 0, got '-1 1 2'"},
        NonPositiveCase{"CylinderRadiusZero", withVisual("shape=\"cylinder\" radius=\"0\" height=\"1.8\""),
                        "<visual", "attribute 'radius' of <visual> must be > 0, got 0"},
        NonPositiveCase{"CylinderHeightNegative", withVisual("shape=\"cylinder\" radius=\"0.3\" height=\"-1.8\""),
                        "<visual", "attribute 'height' of <visual> must be > 0, got -1.8"},
        NonPositiveCase{"PathSpeedZero", withPathSpeed("0"), "<path", "attribute 'speed' of <path> must be > 0, got 0"},
        NonPositiveCase{"PathSpeedNegative", withPathSpeed("-0.5"), "<path",
                        "attribute 'speed' of <path> must be > 0, got -0.5"},
        NonPositiveCase{"DtZero", withHeader("dt=\"0\""), "<scenario", "attribute 'dt' of <scenario> must be > 0, got 0"},
        NonPositiveCase{"DtNegative", withHeader("dt=\"-0.1\""), "<scenario",
                        "attribute 'dt' of <scenario> must be > 0, got -0.1"},
        NonPositiveCase{"DurationZero", withHeader("duration=\"0\""), "<scenario",
                        "attribute 'duration' of <scenario> must be > 0, got 0"},
        NonPositiveCase{"DurationNegative", withHeader("duration=\"-10\""), "<scenario",
                        "attribute 'duration' of <scenario> must be > 0, got -10"},
        NonPositiveCase{"CameraWidthZero", withRobotChild("<camera width=\"0\"/>"), "<camera",
                        "attribute 'width' of <camera> must be a whole number in [1, 1000000], got 0"},
        NonPositiveCase{"CameraHeightNegative", withRobotChild("<camera height=\"-120\"/>"), "<camera",
                        "attribute 'height' of <camera> must be a whole number in [1, 1000000], got -120"},
        NonPositiveCase{"CameraRangeZero", withRobotChild("<camera range=\"0\"/>"), "<camera",
                        "attribute 'range' of <camera> must be > 0, got 0"},
        NonPositiveCase{"CameraHeightAboveGroundZero", withRobotChild("<camera height_above_ground=\"0\"/>"),
                        "<camera", "attribute 'height_above_ground' of <camera> must be > 0, got 0"},
        NonPositiveCase{"MaxSpeedZero", withRobotChild("<limits max_speed=\"0\"/>"), "<limits",
                        "attribute 'max_speed' of <limits> must be > 0, got 0"},
        NonPositiveCase{"AcousticLevelNegative",
                        scenarioWith("  <object id=\"a\" label=\"person\" x=\"5\" y=\"5\">\n"
                                     "    <acoustic sound=\"sounds/beep.wav\" level=\"-1\"/>\n  </object>"),
                        "<acoustic", "attribute 'level' of <acoustic> must be >= 0, got -1"},
        NonPositiveCase{"RobotRadiusZero",
                        "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
                        "  <robot x=\"2\" y=\"2\" radius=\"0\"/>\n</scenario>\n",
                        "<robot", "attribute 'radius' of <robot> must be > 0, got 0"}),
    [](const ::testing::TestParamInfo<NonPositiveCase>& info) { return info.param.name; });

TEST_F(Refusal, CameraWidthNotAnInteger) {
  expectRefused(withRobotChild("<camera width=\"160.5\"/>"), "<camera",
                "attribute 'width' of <camera> is not an integer: '160.5'");
}

TEST_F(Refusal, DtLongerThanDuration) {
  expectRefused(withHeader("dt=\"5\" duration=\"2\""), "<scenario", "dt (5 s) is longer than the duration (2 s)");
}

// --- boxes and colours ---

TEST_F(Refusal, BoxSizeWithTwoNumbers) {
  expectRefused(withVisual("shape=\"box\" size=\"4 0.2\""), "<visual",
                "attribute 'size' of <visual> must be three numbers \"sx sy sz\", got '4 0.2'");
}

TEST_F(Refusal, BoxSizeWithAWord) {
  expectRefused(withVisual("shape=\"box\" size=\"4 wide 2\""), "<visual",
                "attribute 'size' of <visual> has 'wide', which is not a finite number");
}

TEST_F(Refusal, UnknownShape) {
  expectRefused(withVisual("shape=\"sphere\" radius=\"1\""), "<visual",
                "attribute 'shape' of <visual> must be 'box' or 'cylinder', got 'sphere'");
}

TEST_F(Refusal, ColourNamedInsteadOfHex) {
  expectRefused(withVisual("shape=\"box\" size=\"1 1 1\" color=\"red\""), "<visual",
                "attribute 'color' of <visual> must be '#rrggbb', got 'red'");
}

TEST_F(Refusal, ColourWithNonHexDigits) {
  expectRefused(withVisual("shape=\"box\" size=\"1 1 1\" color=\"#12345g\""), "<visual",
                "must be '#rrggbb', got '#12345g'");
}

TEST_F(Refusal, SecondVisualInOneObject) {
  expectRefused(scenarioWith("  <object id=\"a\" label=\"wall\" x=\"5\" y=\"5\">\n"
                             "    <visual shape=\"box\" size=\"1 1 1\"/>\n"
                             "    <visual shape=\"cylinder\" radius=\"1\" height=\"1\"/>\n  </object>"),
                "<visual shape=\"cylinder\"", "<visual> may appear only once in <object>");
}

// --- labels and ids ---

TEST_F(Refusal, LabelNotACategory) {
  expectRefused(scenarioWith("  <object id=\"dog1\" label=\"dog\" x=\"5\" y=\"5\"/>"), "<object",
                "label 'dog' is not a category (categories: person car siren wall fire)");
}

TEST_F(Refusal, LabelNotInTheFilesOwnCategories) {
  expectRefused(scenarioWith("  <categories>person debris</categories>\n"
                             "  <object id=\"w\" label=\"wall\" x=\"5\" y=\"5\"/>"),
                "<object", "label 'wall' is not a category (categories: person debris)");
}

TEST_F(Refusal, AcousticLabelNotACategory) {
  expectRefused(scenarioWith("  <object id=\"radio\" label=\"siren\" x=\"5\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds/beep.wav\" label=\"voice\"/>\n  </object>"),
                "<acoustic", "label 'voice' is not a category");
}

TEST_F(Refusal, EventLabelNotACategory) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"3\" object=\"v1\" label=\"ghost\"/>\n  </events>"),
                "<event ", "label 'ghost' is not a category");
}

TEST_F(Refusal, EmptyCategories) {
  expectRefused(scenarioWith("  <categories>  </categories>"), "<categories", "<categories> lists no labels");
}

TEST_F(Refusal, DuplicateObjectId) {
  expectRefused(scenarioWith(kVictim + "  <object id=\"v1\" label=\"car\" x=\"20\" y=\"5\"/>"),
                "label=\"car\"", "duplicate object id 'v1' (first defined at line 5)");
}

// --- positions ---

TEST_F(Refusal, ObjectOutsideTheWorld) {
  expectRefused(scenarioWith("  <object id=\"far\" label=\"car\" x=\"31\" y=\"5\"/>"), "<object",
                "object 'far' at (31, 5) is outside the world [0, 30] x [0, 20]");
}

TEST_F(Refusal, ObjectBelowTheWorld) {
  expectRefused(scenarioWith("  <object id=\"far\" label=\"car\" x=\"3\" y=\"-0.5\"/>"), "<object",
                "object 'far' at (3, -0.5) is outside the world");
}

TEST_F(Refusal, WaypointOutsideTheWorld) {
  expectRefused(scenarioWith(kObjectA + "  <path object=\"a\" speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                        "    <waypoint x=\"3\" y=\"25\"/>\n  </path>"),
                "y=\"25\"", "waypoint (3, 25) is outside the world [0, 30] x [0, 20]");
}

TEST_F(Refusal, EventMovingAnObjectOutsideTheWorld) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"3\" object=\"v1\" x=\"40\"/>\n  </events>"),
                "<event ", "event moves object 'v1' to (40, 5), outside the world");
}

TEST_F(Refusal, RobotStartOutsideTheWorld) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"35\" y=\"2\"/>\n</scenario>\n",
      "<robot", "robot start (35, 2) with radius 0.35 m does not fit inside the world");
}

TEST_F(Refusal, RobotStartTooCloseToTheWorldEdge) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"0.2\" y=\"2\"/>\n</scenario>\n",
      "<robot", "does not fit inside the world");
}

TEST_F(Refusal, RobotStartInsideAWall) {
  // The wall is rotated by 90 degrees: 4 m along y, 0.2 m along x, centred on (2, 3).
  expectRefused(scenarioWith("  <object id=\"wall1\" label=\"wall\" x=\"2\" y=\"3\" yaw=\"90\">\n"
                             "    <visual shape=\"box\" size=\"4 0.2 2.5\"/>\n  </object>"),
                "<robot", "robot start (2, 2) with radius 0.35 m overlaps object 'wall1' (line 5)");
}

TEST_F(Refusal, RobotStartTouchingACylinder) {
  // Centre 0.6 m away: the robot's 0.35 m disc reaches into the 0.3 m cylinder.
  expectRefused(scenarioWith("  <object id=\"p\" label=\"person\" x=\"2.6\" y=\"2\">\n"
                             "    <visual shape=\"cylinder\" radius=\"0.3\" height=\"1.8\"/>\n  </object>"),
                "<robot", "overlaps object 'p'");
}

TEST_F(Refusal, HeadYawOutsideItsRange) {
  expectRefused(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"2\" y=\"2\" head_yaw=\"100\"/>\n</scenario>\n",
      "<robot", "head_yaw 100 is outside the head's pan range +/-85");
}

TEST_F(Refusal, FieldOfViewOf180Degrees) {
  expectRefused(withRobotChild("<camera fov=\"180\"/>"), "<camera", "fov must be below 180 degrees");
}

// --- paths and events naming objects ---

TEST_F(Refusal, EventNamingUnknownObject) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"3\" object=\"ghost\" activity=\"yelling\"/>\n"
                                       "  </events>"),
                "<event ", "<event> names unknown object 'ghost'");
}

TEST_F(Refusal, PathNamingUnknownObject) {
  expectRefused(scenarioWith(kVictim + "  <path object=\"ghost\" speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                       "    <waypoint x=\"3\" y=\"1\"/>\n  </path>"),
                "<path", "<path> names unknown object 'ghost'");
}

TEST_F(Refusal, PathWithOneWaypoint) {
  expectRefused(scenarioWith(kObjectA + "  <path object=\"a\" speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n  </path>"),
                "<path", "a path needs at least two <waypoint>s, got 1");
}

TEST_F(Refusal, SecondPathForOneObject) {
  const std::string path = "  <path object=\"a\" speed=\"1\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                           "    <waypoint x=\"3\" y=\"1\"/>\n  </path>\n";
  expectRefused(scenarioWith(kObjectA + path + "  <path object=\"a\" speed=\"2\">\n    <waypoint x=\"1\" y=\"1\"/>\n"
                                               "    <waypoint x=\"3\" y=\"1\"/>\n  </path>"),
                "speed=\"2\"", "object 'a' already has a path (line 6)");
}

TEST_F(Refusal, NegativeEventTime) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"-1\" object=\"v1\" activity=\"idle\"/>\n  </events>"),
                "<event ", "event time t must be >= 0, got -1");
}

// --- sound files ---

TEST_F(Refusal, SoundFileThatDoesNotExist) {
  expectRefused(scenarioWith("  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds/missing.wav\"/>\n  </object>"),
                "<acoustic", "sound file 'sounds/missing.wav' does not exist");
}

TEST_F(Refusal, SoundFileThatIsNotAWav) {
  expectRefused(scenarioWith("  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds/not_a_wav.wav\"/>\n  </object>"),
                "<acoustic", "sound file 'sounds/not_a_wav.wav' is not a readable WAV file");
}

TEST_F(Refusal, SoundFileInAnotherAudioFormat) {
  testing::writeTone((dir_ / "sounds" / "tone.aiff").string(), 0.2, SF_FORMAT_AIFF | SF_FORMAT_PCM_16);
  expectRefused(scenarioWith("  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds/tone.aiff\"/>\n  </object>"),
                "<acoustic", "is audio but not a WAV file");
}

TEST_F(Refusal, SoundFileThatIsAFolder) {
  expectRefused(scenarioWith("  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds\"/>\n  </object>"),
                "<acoustic", "sound file 'sounds' is not a regular file");
}

TEST_F(Refusal, EventSoundFileThatDoesNotExist) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"3\" object=\"v1\" sound=\"sounds/nope.wav\"/>\n"
                                       "  </events>"),
                "<event ", "sound file 'sounds/nope.wav' does not exist");
}

// --- flags and congruency ---

TEST_F(Refusal, ActiveOtherThanZeroOrOne) {
  expectRefused(scenarioWith("  <object id=\"v1\" label=\"person\" x=\"10\" y=\"5\">\n"
                             "    <acoustic sound=\"sounds/beep.wav\" active=\"2\"/>\n  </object>"),
                "<acoustic", "attribute 'active' of <acoustic> must be 0 or 1, got '2'");
}

TEST_F(Refusal, EventActiveWrittenAsWord) {
  expectRefused(scenarioWith(kVictim + "  <events>\n    <event t=\"3\" object=\"v1\" active=\"true\"/>\n  </events>"),
                "<event ", "attribute 'active' of <event> must be 0 or 1, got 'true'");
}

TEST_F(Refusal, CongruencyValueAboveOne) {
  expectRefused(scenarioWith("  <congruency>\n    <c label=\"person\" activity=\"yelling\" value=\"1.5\"/>\n"
                             "  </congruency>"),
                "<c ", "congruency value must be in [0, 1], got 1.5");
}

TEST_F(Refusal, CongruencyValueBelowZero) {
  expectRefused(scenarioWith("  <congruency>\n    <c label=\"fire\" activity=\"burning\" value=\"-0.25\"/>\n"
                             "  </congruency>"),
                "<c ", "congruency value must be in [0, 1], got -0.25");
}

// --- acoustics (rendered hearing only) ---

TEST_F(Refusal, SecondAcousticsElement) {
  expectRefused(scenarioWith("  <acoustics reverberation=\"0.6\"/>\n  <acoustics reflection_order=\"1\" />"),
                "<acoustics reflection_order", "<acoustics> may appear only once in <scenario> (first at line 5)");
}

TEST_F(Refusal, EveryBadAcousticsValue) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"reverberation=\"-0.1\"", "attribute 'reverberation' of <acoustics> must be 0 (no tail) or a T60 in (0, 10] s, got -0.1"},
      {"reverberation=\"10.5\"", "attribute 'reverberation' of <acoustics> must be 0 (no tail) or a T60 in (0, 10] s, got 10.5"},
      {"reverberation=\"nan\"", "attribute 'reverberation' of <acoustics> must be a finite number, got 'nan'"},
      {"reverberation=\"slow\"", "attribute 'reverberation' of <acoustics> is not a number: 'slow'"},
      {"reflection_order=\"5\"", "attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got '5'"},
      {"reflection_order=\"-1\"", "attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got '-1'"},
      {"reflection_order=\"1.5\"", "attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got '1.5'"},
      {"reflection_order=\"two\"", "attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got 'two'"},
      {"reflection_order=\"\"", "attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got ''"},
      {"absorption=\"1.2\"", "attribute 'absorption' of <acoustics> must be in [0, 1], got 1.2"},
      {"absorption=\"-0.01\"", "attribute 'absorption' of <acoustics> must be in [0, 1], got -0.01"},
      {"absorption=\"inf\"", "attribute 'absorption' of <acoustics> must be a finite number, got 'inf'"},
      {"ground=\"2\"", "attribute 'ground' of <acoustics> must be 0 or 1, got '2'"},
      {"ground=\"yes\"", "attribute 'ground' of <acoustics> must be 0 or 1, got 'yes'"},
  };
  for (const auto& [attribute, what] : cases) {
    SCOPED_TRACE(attribute);
    expectRefused(scenarioWith(kVictim + "  <acoustics " + attribute + "/>"), "<acoustics", what);
  }
}

TEST_F(Refusal, VisualAbsorptionOutsideZeroToOne) {
  for (const char* value : {"1.5", "-0.2"}) {
    SCOPED_TRACE(value);
    expectRefused(scenarioWith(std::string("  <object id=\"w\" label=\"wall\" x=\"10\" y=\"5\">\n"
                                           "    <visual shape=\"box\" size=\"4 0.2 2.5\" absorption=\"") +
                               value + "\"/>\n  </object>"),
                  "<visual", std::string("attribute 'absorption' of <visual> must be in [0, 1], got ") + value);
  }
}

}  // namespace
}  // namespace beft::scenario
