// The contract every harness checks (fuzz/README.md): a kernel call either throws the
// kernel's InputError (NoMonotoneSolution is one) with a message, or returns a result whose
// every number is finite. Anything else is a finding: the harness prints what broke and
// aborts, and libFuzzer saves the input (crash-<sha1>) with the stack trace.
#pragma once
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Type.hxx>

#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines::fuzz {

// --- The decoded input, printed with a finding ---------------------------------------------

inline std::string format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}
inline std::string format(int x) { return std::to_string(x); }
inline std::string format(bool x) { return x ? "true" : "false"; }
inline std::string format(const char* x) { return x; }
inline std::string format(const std::string& x) { return x; }

/// A vector as [a, b, ...]; a matrix as rows [[...], [...]].
template <class Derived>
std::string format(const Eigen::DenseBase<Derived>& m) {
  std::string out = "[";
  const bool vector = m.rows() == 1 || m.cols() == 1;
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (!vector) out += (i ? ", [" : "[");
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if ((vector && (i || j)) || (!vector && j)) out += ", ";
      out += format(static_cast<double>(m(i, j)));
    }
    if (!vector) out += "]";
  }
  return out + "]";
}

inline std::string format(const BSplineCurve& c) {
  return "{degree " + format(c.degree) + ", periodic " + format(c.periodic) + ", poles " + format(c.poles) +
         ", weights " + format(c.weights) + ", knots " + format(c.knots) + ", mults " + format(c.mults) + "}";
}

/// The decoded input of the current execution, one entry per named value: printed with a
/// finding (copies, formatted only then), or at once with FAIRSPLINES_FUZZ_PRINT=1 in the
/// environment (to see the input of a crash that a sanitizer reports).
class Notes {
public:
  void clear() { items_.clear(); }
  template <class T>
  void add(const char* name, T value) {
    items_.emplace_back(name, [v = std::move(value)] { return format(v); });
    if (printAtOnce_) std::fprintf(stderr, "  %s = %s\n", name, items_.back().second().c_str());
  }
  void print() const {
    std::fprintf(stderr, "==== decoded input:\n");
    for (const auto& [name, text] : items_) std::fprintf(stderr, "  %s = %s\n", name, text().c_str());
  }

private:
  std::vector<std::pair<const char*, std::function<std::string()>>> items_;
  bool printAtOnce_ = std::getenv("FAIRSPLINES_FUZZ_PRINT") != nullptr;
};

inline Notes& notes() {
  static Notes n;
  return n;
}

/// Records a decoded value for the report of a finding.
template <class T>
void note(const char* name, const T& value) {
  notes().add(name, value);
}

// --- Findings ---------------------------------------------------------------------------

/// Thrown by fail() with FAIRSPLINES_FUZZ_KEEP_GOING=1: the harness goes on with the next input.
struct KeptGoing {};

/// FAIRSPLINES_FUZZ_KEEP_GOING=1 in the environment: a finding of the contract (not a
/// sanitizer's, which still aborts) is reported the first time its kind is seen and
/// counted, and fuzzing goes on; the counts are printed at exit. For surveying all the
/// kinds of findings in one long run; `make fuzz` does not set it.
inline bool keepGoing() {
  static const bool on = std::getenv("FAIRSPLINES_FUZZ_KEEP_GOING") != nullptr;
  return on;
}

/// The kind of a finding: its call and message without the numbers of the input (digits
/// that do not continue a name, as in "Array1" or "t_4").
inline std::string kindOf(const std::string& call, const std::string& what) {
  const std::string kind = call + ": " + what.substr(0, what.find(" ("));
  std::string out;
  bool inName = false;
  for (char c : kind) {
    const bool letter = std::isalpha(static_cast<unsigned char>(c)) || c == '_';
    if (std::isdigit(static_cast<unsigned char>(c)) && !inName) continue;
    if (!std::isdigit(static_cast<unsigned char>(c))) inName = letter;
    out += c;
  }
  return out;
}

inline std::map<std::string, long>& kinds() {
  static std::map<std::string, long>* counts = [] {
    auto* m = new std::map<std::string, long>;
    std::atexit([] {
      if (kinds().empty()) return;
      std::fprintf(stderr, "==== FairSplines fuzz findings by kind (kept going):\n");
      for (const auto& [kind, n] : kinds()) std::fprintf(stderr, "  %8ld  %s\n", n, kind.c_str());
    });
    return m;
  }();
  return *counts;
}

/// The bytes of the current execution (set by runOne), saved with the first finding of a
/// kind in keep-going mode.
inline std::pair<const uint8_t*, size_t>& currentInput() {
  static std::pair<const uint8_t*, size_t> input{nullptr, 0};
  return input;
}

/// Prints the finding and the decoded input and aborts (libFuzzer reports the abort with a
/// stack trace and saves the input); with keepGoing(), reports only the first of each kind,
/// saves its input as finding-<hash of the kind> in FAIRSPLINES_FUZZ_FINDINGS (a folder,
/// default the current one) and throws KeptGoing.
[[noreturn]] inline void fail(const std::string& call, const std::string& what) {
  if (keepGoing()) {
    const std::string kind = kindOf(call, what);
    if (kinds()[kind]++ == 0) {
      const char* folder = std::getenv("FAIRSPLINES_FUZZ_FINDINGS");
      char name[32];
      std::snprintf(name, sizeof name, "finding-%016zx", std::hash<std::string>{}(kind));
      const std::string path = std::string(folder ? folder : ".") + "/" + name;
      if (FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(currentInput().first, 1, currentInput().second, f);
        std::fclose(f);
      }
      std::fprintf(stderr, "\n==== FairSplines fuzz finding in %s: %s (first of its kind, input %s; going on)\n",
                   call.c_str(), what.c_str(), path.c_str());
      notes().print();
    }
    throw KeptGoing{};
  }
  std::fprintf(stderr, "\n==== FairSplines fuzz finding in %s: %s\n", call.c_str(), what.c_str());
  notes().print();
  std::fflush(stderr);
  std::abort();
}

/// Runs one kernel call under the contract: an InputError with a message is the kernel
/// refusing the input (fine); any other exception escaping is a finding. Returns whether
/// the call returned (so the caller checks the result).
template <class F>
bool guarded(const char* call, F&& f) {
  try {
    f();
    return true;
  } catch (const KeptGoing&) {
    throw;
  } catch (const InputError& e) {
    if (e.what()[0] == '\0') fail(call, "InputError without a message");
    return false;
  } catch (const Standard_Failure& e) {
    fail(call, std::string("OpenCASCADE's ") + e.DynamicType()->Name() + " escaped: " + e.GetMessageString());
  } catch (const std::exception& e) {
    fail(call, std::string("an exception other than InputError escaped: ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fail(call, "an exception of unknown type escaped");
  }
}

template <class Derived>
void requireFinite(const char* call, const char* what, const Eigen::DenseBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (!std::isfinite(m(i, j))) {
        fail(call, std::string("non-finite ") + what + " (" + std::to_string(m(i, j)) + " at row " + std::to_string(i) +
                       ", column " + std::to_string(j) + " of " + std::to_string(m.rows()) + " x " +
                       std::to_string(m.cols()) + ")");
      }
    }
  }
}

inline void requireFinite(const char* call, const char* what, double x) {
  if (!std::isfinite(x)) fail(call, std::string("non-finite ") + what + " (" + std::to_string(x) + ")");
}

/// A returned B-spline: finite poles, weights and knots, and OCCT accepts it (a curve the
/// kernel returns must convert: the workbench hands every one to FreeCAD).
inline void requireValid(const char* call, const BSplineCurve& c) {
  requireFinite(call, "pole", c.poles);
  requireFinite(call, "weight", c.weights);
  requireFinite(call, "knot", c.knots);
  try {
    toOcct(c);
  } catch (const InputError& e) {
    fail(call, std::string("the returned B-spline is not valid for OpenCASCADE: ") + e.what());
  } catch (const Standard_Failure& e) {
    fail(call, std::string("the returned B-spline is not valid for OpenCASCADE: ") + e.GetMessageString());
  }
}

inline void requireValid(const char* call, const Handle(Geom_BSplineCurve)& c) {
  if (c.IsNull()) fail(call, "a null curve");
  for (int i = 1; i <= c->NbPoles(); ++i) {
    const gp_Pnt p = c->Pole(i);
    if (!std::isfinite(p.X()) || !std::isfinite(p.Y()) || !std::isfinite(p.Z())) fail(call, "non-finite pole");
    if (!std::isfinite(c->Weight(i))) fail(call, "non-finite weight");
  }
  for (int i = 1; i <= c->NbKnots(); ++i) {
    if (!std::isfinite(c->Knot(i))) fail(call, "non-finite knot");
  }
}

inline void requireValid(const char* call, const Handle(Geom_BSplineSurface)& s) {
  if (s.IsNull()) fail(call, "a null surface");
  for (int i = 1; i <= s->NbUPoles(); ++i) {
    for (int j = 1; j <= s->NbVPoles(); ++j) {
      const gp_Pnt p = s->Pole(i, j);
      if (!std::isfinite(p.X()) || !std::isfinite(p.Y()) || !std::isfinite(p.Z())) fail(call, "non-finite pole");
      if (!std::isfinite(s->Weight(i, j))) fail(call, "non-finite weight");
    }
  }
  for (int i = 1; i <= s->NbUKnots(); ++i) {
    if (!std::isfinite(s->UKnot(i))) fail(call, "non-finite u knot");
  }
  for (int i = 1; i <= s->NbVKnots(); ++i) {
    if (!std::isfinite(s->VKnot(i))) fail(call, "non-finite v knot");
  }
}

/// One execution of a harness: the decoded input starts empty, `fuzzOne` reads the bytes
/// and calls the kernel. Every harness's LLVMFuzzerTestOneInput is this.
template <class FuzzInputT>
int runOne(const uint8_t* data, size_t size, int (*fuzzOne)(FuzzInputT&)) {
  FuzzInputT in(data, size);
  notes().clear();
  currentInput() = {data, size};
  try {
    fuzzOne(in);
  } catch (const KeptGoing&) {
  }
  return 0;
}

}  // namespace fairsplines::fuzz
