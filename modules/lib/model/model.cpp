#include "lib/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beft::model {

namespace {
double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }
constexpr double kRadToDeg = 180.0 / M_PI;
}  // namespace

double wrapDegrees(double angle_deg) {
  double a = std::fmod(angle_deg, 360.0);  // (-360, 360)
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

double distance(double px, double py, double pz, double ox, double oy, double oz) {
  return std::sqrt((ox - px) * (ox - px) + (oy - py) * (oy - py) + (oz - pz) * (oz - pz));
}

double azimuth(double px, double py, double nose_heading_deg, double ox, double oy) {
  const double bearing = std::atan2(oy - py, ox - px) * kRadToDeg;
  return wrapDegrees(bearing - nose_heading_deg);
}

double distanceDegradation(double d) { return 1.0 - 1.0 / (1.0 + std::exp(-(d - 10.0) / 2.0)); }

double azimuthDegradation(double alpha_deg, const Parameters& p) {
  return std::exp(-0.5 * alpha_deg * alpha_deg / p.aw_variance_deg2);
}

double visualOcclusionDegradation(double occlusion_pct) { return 1.0 - occlusion_pct / 100.0; }

double acousticOcclusionDegradation(double occlusion_pct) {
  return 1.0 - 0.8 * occlusion_pct / 100.0;
}

double visualPerceptibility(double d, double occlusion_pct) {  // eq. 1
  return distanceDegradation(d) * visualOcclusionDegradation(occlusion_pct);
}

double acousticPerceptibility(double d, double occlusion_pct, double alpha_deg,
                              const Parameters& p) {  // eq. 2
  return distanceDegradation(d) * acousticOcclusionDegradation(occlusion_pct) *
         azimuthDegradation(alpha_deg, p);
}

double labelConfidence(bool is_true_category, double perceptibility, const Parameters& p) {
  // Eq. 3. Default: a logistic of gain g around P = 0.5 (reaches ~1 / ~0 at
  // P = 1). Printed: 1 + 20 exp(-(P - 0.5)) in the denominator, as in the paper.
  const double x = perceptibility - 0.5;
  const double spread = p.label_form == LabelForm::Printed
                            ? 0.5 / (1.0 + 20.0 * std::exp(-x))
                            : 0.5 / (1.0 + std::exp(-p.label_gain * x));
  return is_true_category ? 0.5 + spread : 0.5 - spread;
}

std::vector<double> labelConfidences(const std::vector<std::string>& categories,
                                     const std::string& true_label, double perceptibility,
                                     const Parameters& p) {
  std::vector<double> confidences;
  labelConfidences(categories, true_label, perceptibility, p, confidences);
  return confidences;
}

void labelConfidences(const std::vector<std::string>& categories, const std::string& true_label,
                      double perceptibility, const Parameters& p, std::vector<double>& out) {
  out.clear();
  out.reserve(categories.size());
  for (const auto& category : categories) out.push_back(labelConfidence(category == true_label, perceptibility, p));
}

namespace {
// The shared term of eq. 4: log(min(t, T_max)) / (2 log n), t >= 1.
double curveTerm(int t, const Parameters& p) {
  const int steps = std::max(1, std::min(t, p.t_max));
  return std::log(static_cast<double>(steps)) / (2.0 * std::log(p.n));
}
}  // namespace

double weightRising(int t, double c, const Parameters& p) { return clamp01(curveTerm(t, p) + c); }

double weightFalling(int t, double c, const Parameters& p) {
  return clamp01(2.0 * c - (curveTerm(t, p) + c));
}

void declareParameters(DeclaredParameters& declared, Parameters& p, const std::vector<std::string>& names) {
  const auto wanted = [&](const char* name) {
    return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
  };
  constexpr double kNoLimit = DeclaredParameters::kNoLimit;
  if (wanted("aw_variance_deg2"))
    declared.declare("aw_variance_deg2", p.aw_variance_deg2, 0, kNoLimit,
                     "variance s of a_w(alpha) in eq. 2 [deg^2]; the paper prints 90", true);
  if (wanted("label_gain"))
    declared.declare("label_gain", p.label_gain, 0, kNoLimit, "gain g of eq. 3 (default form)", true);
  if (wanted("label_form"))
    declared.declareChoice("label_form", p.label_form,
                           {{"default", LabelForm::Default}, {"printed", LabelForm::Printed}},
                           "eq. 3 form: default (logistic with gain g) or printed (the paper's literal formula)");
  if (wanted("t_max"))
    declared.declare("t_max", p.t_max, 2, 1000000, "T_max of eq. 4: curve length and re-evaluation delay [steps]");
  if (wanted("n")) declared.declare("n", p.n, 1, kNoLimit, "n of eq. 4 (T_max^2: one curve spans 0.25)", true);
}

void setParameter(Parameters& p, const std::string& name, const std::string& value) {
  DeclaredParameters declared;
  declareParameters(declared, p);
  declared.set(name, value);
}

}  // namespace beft::model
