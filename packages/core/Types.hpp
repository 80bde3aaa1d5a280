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

using Scalar = double;
using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Vector = Tpetra::Vector<Scalar, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<Scalar, LO, GO, Node>;
using CrsMatrix = Tpetra::CrsMatrix<Scalar, LO, GO, Node>;
using Operator = Tpetra::Operator<Scalar, LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

using ExecSpace = Node::execution_space;
using MemSpace = Node::memory_space;
using DeviceType = Node::device_type;
/// Scatter-adds from assembly kernels need atomics only where cells run concurrently.
#ifdef KOKKOS_ENABLE_SERIAL
inline constexpr bool kAtomicScatter = !std::is_same_v<ExecSpace, Kokkos::Serial>;
#else
inline constexpr bool kAtomicScatter = true;
#endif

template <class T>
using RCP = Teuchos::RCP<T>;

}  // namespace signorini
