#include "corlab/restitution/model_info.hpp"

namespace corlab::restitution {

std::string_view to_string(Status status) {
  switch (status) {
    case Status::kVerifiedPaper:
      return "verified-paper";
    case Status::kVerifiedSecondSource:
      return "verified-second-source";
    case Status::kVerifiedDataset:
      return "verified-dataset";
    case Status::kUnverified:
      return "unverified";
  }
  return "unverified";
}

}  // namespace corlab::restitution
