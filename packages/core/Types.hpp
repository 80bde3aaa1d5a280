#pragma once
#include <type_traits>
/// \file Types.hpp
/// Tpetra/Kokkos type aliases shared by every signorini package.
#include <Kokkos_Core.hpp>
#include <Teuchos_RCP.hpp>
#include <Teuchos_Comm.hpp>
#include <Tpetra_Map_decl.hpp>
#include <Tpetra_Vector_decl.hpp>
#include <Tpetra_MultiVector_decl.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>
#include <Tpetra_Operator.hpp>

namespace signorini {

using Scalar = double;                                         ///< matrix and vector entries
using Map = Tpetra::Map<>;                                     ///< distribution of rows/entries over the ranks
using LO = Map::local_ordinal_type;                            ///< local (per-rank) index
using GO = Map::global_ordinal_type;                           ///< global index
using Node = Map::node_type;                                   ///< Tpetra's Kokkos node (Trilinos' default)
using Vector = Tpetra::Vector<Scalar, LO, GO, Node>;           ///< distributed vector
using MultiVector = Tpetra::MultiVector<Scalar, LO, GO, Node>; ///< distributed set of vectors
using CrsMatrix = Tpetra::CrsMatrix<Scalar, LO, GO, Node>;     ///< distributed sparse matrix
using Operator = Tpetra::Operator<Scalar, LO, GO, Node>;       ///< linear operator (e.g. a preconditioner)
using Comm = Teuchos::Comm<int>;                               ///< the MPI communicator as Teuchos wraps it

using ExecSpace = Node::execution_space;  ///< where the Kokkos kernels run
using MemSpace = Node::memory_space;      ///< where the Kokkos views live
using DeviceType = Node::device_type;     ///< ExecSpace and MemSpace together
/// Scatter-adds from assembly kernels need atomics only where cells run concurrently.
#ifdef KOKKOS_ENABLE_SERIAL
inline constexpr bool kAtomicScatter = !std::is_same_v<ExecSpace, Kokkos::Serial>;
#else
inline constexpr bool kAtomicScatter = true;
#endif

/// Teuchos' reference-counted pointer (shared ownership).
template <class T>
using RCP = Teuchos::RCP<T>;

}  // namespace signorini
