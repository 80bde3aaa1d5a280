#include "Forest.hpp"

#include <p4est_extended.h>
#include <sc.h>

namespace signorini::mesh {

void initializeP4est(MPI_Comm comm) {
  static bool initialized = false;
  if (initialized) return;
  sc_init(comm, 0, 0, nullptr, SC_LP_ERROR);
  p4est_init(nullptr, SC_LP_ERROR);
  initialized = true;
}

Forest::Forest(std::shared_ptr<const CoarseMesh> coarse, MPI_Comm comm, int level) : coarse_(std::move(coarse)) {
  initializeP4est(comm);
  p4est_ = p4est_new_ext(comm, coarse_->connectivity(), 0, level, 1, 0, nullptr, nullptr);
}

Forest::Forest(const Forest& other) : coarse_(other.coarse_), p4est_(p4est_copy(other.p4est_, 0)) {}

Forest::~Forest() {
  if (p4est_) p4est_destroy(p4est_);
}

namespace {
int refineCallback(p4est_t* p, p4est_topidx_t tree, p4est_quadrant_t* q) {
  const auto& f = *static_cast<const std::function<bool(int, const p4est_quadrant_t&)>*>(p->user_pointer);
  return f(static_cast<int>(tree), *q) ? 1 : 0;
}
}  // namespace

void Forest::refineIf(const std::function<bool(int tree, const p4est_quadrant_t& q)>& refine) {
  void* saved = p4est_->user_pointer;
  p4est_->user_pointer = const_cast<void*>(static_cast<const void*>(&refine));
  p4est_refine(p4est_, 0, refineCallback, nullptr);
  p4est_->user_pointer = saved;
}

void Forest::balance() { p4est_balance(p4est_, P4EST_CONNECT_FULL, nullptr); }

void Forest::partition() { p4est_partition(p4est_, 0, nullptr); }

}  // namespace signorini::mesh
