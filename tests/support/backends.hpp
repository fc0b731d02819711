#pragma once
// The max-flow backends this build has, as a type list for TEMPLATE_TEST_CASE.

#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"
#define C2F_MAXFLOW_BACKENDS c2f::DynamicMaxFlow, c2f::BoostMaxFlow, c2f::KolmogorovMaxFlow
#else
#define C2F_MAXFLOW_BACKENDS c2f::DynamicMaxFlow, c2f::BoostMaxFlow
#endif
