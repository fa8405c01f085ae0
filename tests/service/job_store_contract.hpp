#pragma once
// The job-store contract's fixture: one test body, run against SQLite and against PostgreSQL (a
// throwaway server started by the test process) by job_store_contract_test.cpp's instantiation;
// the tests are in job_store_contract_test.cpp and job_store_recovery_test.cpp.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "store_test_support.hpp"

namespace fosls::service::testing {

class JobStoreContract : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    db_ = std::make_unique<StoreUnderTest>(GetParam());
    store_ = db_->open();
  }
  JobStore& store() { return *store_; }

  std::int64_t submit(const std::string& body) {
    return store().submit(make_job(body), kUnlimited).job->id;
  }

  std::unique_ptr<StoreUnderTest> db_;
  std::unique_ptr<JobStore> store_;
};

}  // namespace fosls::service::testing
