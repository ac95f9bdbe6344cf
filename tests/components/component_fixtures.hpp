#pragma once
// The one list of flight components (component_list.hpp) as gtest types, for typed suites
// (TYPED_TEST_SUITE(Suite, adcs::test::FlightComponents, adcs::test::ComponentNames)).
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "component_list.hpp"

namespace adcs::test {

template <class Tuple>
struct AsGtestTypes;
template <class... C>
struct AsGtestTypes<std::tuple<C...>> {
  using type = ::testing::Types<C...>;
};

using FlightComponents = AsGtestTypes<FlightComponentList>::type;

//! Test names from the fixtures (gtest's NameGenerator): ComponentContract/MrpPd4.IsAComponent.
struct ComponentNames {
  template <class C>
  static std::string GetName(int) {
    return ComponentFixture<C>::name;
  }
};

}  // namespace adcs::test
