#include "core/metrics/fabric.hpp"

#include <Eigen/Eigenvalues>

namespace fp {
namespace {

template <int D>
using Mat = Eigen::Matrix<double, D, D>;

template <int D>
FabricTensor make_tensor(const Mat<D>& sum, std::uint64_t count) {
  FabricTensor f;
  f.count = count;
  const Mat<D> t = count > 0 ? Mat<D>(sum / static_cast<double>(count)) : Mat<D>::Zero();
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) f.tensor.push_back(t(a, b));
  const Eigen::SelfAdjointEigenSolver<Mat<D>> eig(t, Eigen::EigenvaluesOnly);
  for (int a = 0; a < D; ++a) f.eigenvalues.push_back(eig.eigenvalues()[a]);
  return f;
}

}  // namespace

template <int D>
Fabric fabric_tensors(const Packing<D>& packing, const std::vector<PairContact>& contacts) {
  return fabric_tensors<D>(packing.size(), contacts, centre_lines(packing, contacts));
}

template <int D>
Fabric fabric_tensors(std::size_t particles, const std::vector<PairContact>& contacts,
                      const std::vector<Vec<D>>& directions) {
  const std::vector<std::uint32_t> m = coordination_numbers(particles, contacts);
  Mat<D> per_contact = Mat<D>::Zero(), per_particle = Mat<D>::Zero();
  std::uint64_t used = 0;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const PairContact& c = contacts[k];
    const Vec<D>& d = directions[k];
    const double len2 = d.squaredNorm();
    if (!(len2 > 0.0)) continue;
    const Mat<D> nn = d * d.transpose() / len2;
    per_contact += nn;
    per_particle += (1.0 / m[c.i] + 1.0 / m[c.j]) * nn;
    ++used;
  }
  std::uint64_t touching = 0;
  for (const std::uint32_t z : m) touching += z > 0 ? 1 : 0;
  return {make_tensor<D>(per_contact, used), make_tensor<D>(per_particle, touching)};
}

template <int D>
FabricTensor fabric_of_directions(const std::vector<Vec<D>>& directions) {
  Mat<D> sum = Mat<D>::Zero();
  std::uint64_t used = 0;
  for (const Vec<D>& d : directions) {
    const double len2 = d.squaredNorm();
    if (!(len2 > 0.0)) continue;
    sum += d * d.transpose() / len2;
    ++used;
  }
  return make_tensor<D>(sum, used);
}

template Fabric fabric_tensors<2>(const Packing<2>&, const std::vector<PairContact>&);
template Fabric fabric_tensors<3>(const Packing<3>&, const std::vector<PairContact>&);
template Fabric fabric_tensors<2>(std::size_t, const std::vector<PairContact>&, const std::vector<Vec<2>>&);
template Fabric fabric_tensors<3>(std::size_t, const std::vector<PairContact>&, const std::vector<Vec<3>>&);
template FabricTensor fabric_of_directions<2>(const std::vector<Vec<2>>&);
template FabricTensor fabric_of_directions<3>(const std::vector<Vec<3>>&);

}  // namespace fp
