#include "campaign/envelopes_h5.hpp"

#include <hdf5.h>

#include <stdexcept>

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

//! Owns one HDF5 identifier; closes it with the matching H5*close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const char* what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error(std::string("HDF5: ") + what + " failed");
  }
  ~Handle() { close_(id_); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t e, const char* what) {
  if (e < 0) throw std::runtime_error(std::string("HDF5: ") + what + " failed");
}

void write_dataset(hid_t group, const char* name, const std::vector<hsize_t>& dims, const double* data, hid_t dcpl) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, "H5Screate_simple");
  Handle set(H5Dcreate2(group, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
             "H5Dcreate2");
  check(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "H5Dwrite");
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

void write_envelopes_h5(const std::string& path, const std::vector<Envelope>& envelopes) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions here, not stderr text
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "H5Fcreate");
  // No modification times in the object headers: the same envelopes give the same file.
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "H5Pcreate(dataset)");
  check(H5Pset_obj_track_times(dcpl.get(), false), "H5Pset_obj_track_times");
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "H5Pcreate(group)");
  check(H5Pset_obj_track_times(gcpl.get(), false), "H5Pset_obj_track_times");
  for (const Envelope& e : envelopes) {
    Handle g(H5Gcreate2(file.get(), e.name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose, "H5Gcreate2");
    const hsize_t n = e.t.size();
    write_dataset(g.get(), "t", {n}, e.t.data(), dcpl.get());
    std::vector<double> p;
    for (const auto& row : e.percentiles) p.insert(p.end(), row.begin(), row.end());
    write_dataset(g.get(), "percentiles", {static_cast<hsize_t>(kEnvelopeLevelCount), n}, p.data(), dcpl.get());
    write_dataset(g.get(), "levels", {static_cast<hsize_t>(kEnvelopeLevelCount)}, kEnvelopeLevels, dcpl.get());
    write_dataset(g.get(), "mean", {n}, e.mean.data(), dcpl.get());
    Handle aspace(H5Screate(H5S_SCALAR), H5Sclose, "H5Screate");
    Handle attr(H5Acreate2(g.get(), "runs", H5T_STD_U64LE, aspace.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                "H5Acreate2");
    const unsigned long long runs = e.runs;
    check(H5Awrite(attr.get(), H5T_NATIVE_ULLONG, &runs), "H5Awrite");
  }
}

}  // namespace adcs::sim::campaign
