#include "fairsplines/parameters.hpp"

#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"

namespace fairsplines {

Parametrization parseParametrization(const std::string& name) {
  if (name == "chordal") return Parametrization::Chordal;
  if (name == "centripetal") return Parametrization::Centripetal;
  if (name == "uniform") return Parametrization::Uniform;
  throw InputError("unknown parametrization '" + name + "': use 'chordal', 'centripetal' or 'uniform'");
}

SampleInfo validateSamples(PointsRef q, bool closed, int minPoints, const char* method) {
  const Eigen::Index n = q.rows();
  if (q.cols() != 2 && q.cols() != 3) {
    std::ostringstream msg;
    msg << "points must have 2 or 3 coordinates, got " << q.cols();
    throw InputError(msg.str());
  }
  if (n < minPoints) {
    std::ostringstream msg;
    msg << method << " needs at least " << minPoints << (closed ? " points on a closed curve" : " points")
        << ", got " << n;
    throw InputError(msg.str());
  }
  if (!q.allFinite()) {
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!q.row(i).allFinite()) {
        std::ostringstream msg;
        msg << "point " << i << " is not finite (NaN or infinity)";
        throw InputError(msg.str());
      }
    }
  }
  // Coincidence is judged relative to the size of the data.
  const Eigen::RowVectorXd lo = q.colwise().minCoeff(), hi = q.colwise().maxCoeff();
  SampleInfo info;
  info.size = (hi - lo).norm();
  if (info.size <= 1e-300 || info.size <= 1e-14 * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff())) {
    throw InputError("all points coincide");
  }
  const double tol = 1e-12 * info.size;
  const Eigen::Index segments = closed ? n : n - 1;
  info.chords.resize(segments);
  const int dim = static_cast<int>(q.cols());
  const double* data = q.data();
  for (Eigen::Index i = 0; i < segments; ++i) {
    const Eigen::Index j = i + 1 == n ? 0 : i + 1;
    double squared = 0.0;
    for (int c = 0; c < dim; ++c) {
      const double d = data[dim * j + c] - data[dim * i + c];
      squared += d * d;
    }
    info.chords[i] = std::sqrt(squared);
    if (info.chords[i] <= tol) {
      std::ostringstream msg;
      msg << "points " << i << " and " << j << " coincide";
      if (closed && j == 0) msg << " (the last point repeats the first: leave it out for closed data)";
      throw InputError(msg.str());
    }
  }
  return info;
}

Eigen::VectorXd parameters(const Eigen::VectorXd& chords, Parametrization kind) {
  Eigen::VectorXd t(chords.size() + 1);
  t[0] = 0.0;
  for (Eigen::Index i = 0; i < chords.size(); ++i) {
    double h = 1.0;
    if (kind == Parametrization::Chordal) h = chords[i];
    else if (kind == Parametrization::Centripetal) h = std::sqrt(chords[i]);
    t[i + 1] = t[i] + h;
  }
  return t;
}

Eigen::VectorXd parameters(PointsRef q, Parametrization kind, bool closed) {
  const Eigen::Index n = q.rows(), segments = closed ? n : n - 1;
  Eigen::VectorXd chords(segments);
  for (Eigen::Index i = 0; i < segments; ++i) chords[i] = (q.row(i + 1 == n ? 0 : i + 1) - q.row(i)).norm();
  return parameters(chords, kind);
}

Eigen::VectorXd validatedParameters(const Eigen::VectorXd& t, Eigen::Index n, bool closed) {
  const Eigen::Index expected = closed ? n + 1 : n;
  if (t.size() != expected) {
    std::ostringstream msg;
    msg << "expected " << expected << " parameters" << (closed ? " (one more than points, closing the loop)" : "")
        << ", got " << t.size();
    throw InputError(msg.str());
  }
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) {
      std::ostringstream msg;
      msg << "parameter " << i << " is not finite";
      throw InputError(msg.str());
    }
    if (i > 0 && !(t[i] > t[i - 1])) {
      std::ostringstream msg;
      msg << "parameters must increase strictly: t[" << i << "] = " << t[i] << " <= t[" << i - 1 << "] = " << t[i - 1];
      throw InputError(msg.str());
    }
  }
  return t;
}

}  // namespace fairsplines
