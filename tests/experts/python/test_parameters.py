import unittest

from beft_expert.parameters import NO_LIMIT, DeclaredParameters


class DeclaredParametersTest(unittest.TestCase):
    def setUp(self):
        self.p = DeclaredParameters()
        self.p.number("dw_step_s", 0.5, 1e-6, NO_LIMIT, "step [s]")
        self.p.number("n", 100, 1, NO_LIMIT, "n", low_open=True)
        self.p.whole("t_max", 10, 1, 1000000, "T_max")
        self.p.flag("reflex", True, "reflex")
        self.p.text("danger_labels", "fire", "hazards")

    def test_describe_reads_as_the_cpp_list(self):
        self.assertEqual(self.p.describe(),
                         "  dw_step_s (default 0.5, >= 1e-06): step [s]\n"
                         "  n (default 100, > 1): n\n"
                         "  t_max (default 10, whole number in [1, 1000000]): T_max\n"
                         "  reflex (default 1, 0|1): reflex\n"
                         "  danger_labels (default fire, text): hazards\n")

    def test_values_are_set_within_their_ranges(self):
        self.p.set("t_max", "20")
        self.p.set("reflex", "off")
        self.p.set("n", "2.5")
        self.assertEqual((self.p["t_max"], self.p["reflex"], self.p["n"]), (20, False, 2.5))

    def test_out_of_range_and_unknown_names_are_refused_by_name(self):
        with self.assertRaisesRegex(ValueError, r"parameter n='1' is not > 1"):
            self.p.set("n", "1")
        with self.assertRaisesRegex(ValueError, "whole number"):
            self.p.set("t_max", "2.5")
        with self.assertRaisesRegex(ValueError, "unknown parameter 'x' .known: dw_step_s, n"):
            self.p.set("x", "1")
        with self.assertRaises(ValueError):
            self.p.set("dw_step_s", "inf")

    def test_reset_brings_back_the_defaults(self):
        self.p.set("t_max", "3")
        self.p.reset_to_defaults()
        self.assertEqual(self.p["t_max"], 10)


if __name__ == "__main__":
    unittest.main()
