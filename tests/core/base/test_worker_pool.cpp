// The helper-thread pool of the multibody system: every task runs exactly once per batch over
// many batches, tasks really run on two threads, exceptions come back (the lowest index, as a
// sequential loop), a pool of one runs inline; and a system with two concurrent force elements
// gives the same forces and Jacobians bit for bit with 1 and 2 threads.
#include <QtTest>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>

#include "core/base/worker_pool.hpp"
#include "core/multibody/multibody_system.hpp"

using namespace filmdyn;
using namespace filmdyn::multibody;

namespace {

// A nonlinear spring-damper between a body and the ground, declared concurrent; it records the
// thread it ran on.
class RecordingSpring final : public ForceElement {
 public:
  RecordingSpring(BodyIndex body, double k, std::set<std::thread::id>* threads, std::mutex* mutex,
                  const std::atomic<bool>* rendezvous = nullptr)
      : ForceElement("spring"),
        body_(body),
        k_(k),
        threads_(threads),
        mutex_(mutex),
        rendezvous_(rendezvous) {}
  std::vector<BodyIndex> Bodies() const override { return {body_}; }
  bool ProvidesJacobian() const override { return true; }
  bool Concurrent() const override { return true; }
  void AddForces(double, const SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                 ForceJacobian* jacobian) override {
    {
      std::lock_guard lock(*mutex_);
      threads_->insert(std::this_thread::get_id());
    }
    // Side by side must be seen even on a loaded machine (a worker must wake and take another
    // element): while `rendezvous` is set, wait until a second thread has entered (up to 10 s;
    // a pool that runs the elements one after the other fails the test then). Otherwise a
    // short pause, long enough for the threads to overlap in the Jacobian test.
    if (rendezvous_ && rendezvous_->load()) {
      for (int k = 0; k < 10000; ++k) {
        {
          std::lock_guard lock(*mutex_);
          if (threads_->size() >= 2) break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const BodyState b = state.Body(body_);
    for (int c = 0; c < 3; ++c) {
      q_force[3 * body_ + c] += -k_ * b.q[c] * (1.0 + b.q[c] * b.q[c]) - 0.1 * k_ * b.v[c];
      if (jacobian) {
        jacobian->dq(3 * body_ + c, 3 * body_ + c) += -k_ * (1.0 + 3.0 * b.q[c] * b.q[c]);
        jacobian->dv(3 * body_ + c, 3 * body_ + c) += -0.1 * k_;
      }
    }
  }

 private:
  BodyIndex body_;
  double k_;
  std::set<std::thread::id>* threads_;
  std::mutex* mutex_;
  const std::atomic<bool>* rendezvous_;
};

}  // namespace

class TestWorkerPool : public QObject {
  Q_OBJECT
 private slots:
  void everyTaskRunsOncePerBatch() {
    WorkerPool pool(2);
    QCOMPARE(pool.Threads(), 2);
    for (int batch = 0; batch < 2000; ++batch) {
      const int count = 1 + batch % 5;
      std::vector<std::atomic<int>> runs(count);
      pool.Run(count, [&](int k) { ++runs[k]; });
      for (int k = 0; k < count; ++k) QCOMPARE(runs[k].load(), 1);
    }
  }
  void tasksOverlapOnTwoThreads() {
    // Each task of a batch waits (up to 10 s) until the other has started: a pool that ran them
    // one after the other would keep the first waiting and fail; on a loaded machine the second
    // thread only needs to wake within the wait (a fixed pause failed under load: the caller
    // could finish the first task and take the second before the worker woke).
    WorkerPool pool(2);
    std::mutex mutex;
    std::set<std::thread::id> ids;
    std::atomic<int> most{0};
    for (int batch = 0; batch < 20; ++batch) {
      std::atomic<int> started{0}, inside{0};
      pool.Run(2, [&](int) {
        ++inside;  // before `started`: whoever sees both started sees both inside
        ++started;
        {
          std::lock_guard lock(mutex);
          ids.insert(std::this_thread::get_id());
        }
        for (int k = 0; k < 10000 && started.load() < 2; ++k)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const int now = inside.load();
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        --inside;
      });
    }
    QCOMPARE(int(ids.size()), 2);
    QCOMPARE(most.load(), 2);  // both tasks of a batch ran at the same time
  }
  void exceptionsReachTheCaller() {
    for (int threads : {1, 2}) {
      WorkerPool pool(threads);
      std::atomic<int> ran{0};
      try {
        pool.Run(4, [&](int k) {
          ++ran;
          if (k == 1 || k == 3) throw std::runtime_error("task " + std::to_string(k));
        });
        QFAIL("no exception");
      } catch (const std::runtime_error& e) {
        QCOMPARE(std::string(e.what()), std::string("task 1"));
      }
      QCOMPARE(ran.load(), 4);  // the other tasks still ran
      std::atomic<int> after{0};  // tasks run side by side (a plain int was a data race: TSan)
      pool.Run(3, [&](int) { ++after; });  // the pool is still usable
      QCOMPARE(after.load(), 3);
    }
  }
  void singleThreadRunsInline() {
    WorkerPool pool(1);
    QCOMPARE(pool.Threads(), 1);
    std::set<std::thread::id> ids;
    pool.Run(5, [&](int) { ids.insert(std::this_thread::get_id()); });
    QCOMPARE(int(ids.size()), 1);
    QVERIFY(*ids.begin() == std::this_thread::get_id());
  }
  void systemResultsDoNotDependOnThreads() {
    std::mutex mutex;
    std::set<std::thread::id> ids;
    std::atomic<bool> rendezvous{false};
    auto build = [&] {
      auto sys = std::make_unique<MultibodySystem>();
      Body a;
      a.mass = 2.0;
      a.inertia = 0.3;
      Body b = a;
      b.mass = 5.0;
      sys->AddBody(a);
      sys->AddBody(b);
      sys->AddForceElement(std::make_unique<RecordingSpring>(0, 1e3, &ids, &mutex, &rendezvous));
      sys->AddForceElement(std::make_unique<RecordingSpring>(1, 3e3, &ids, &mutex, &rendezvous));
      sys->AddForceElement(std::make_unique<RecordingSpring>(0, 7e2, &ids, &mutex, &rendezvous));
      return sys;
    };
    auto one = build(), two = build();
    two->SetThreads(2);
    QCOMPARE(one->Threads(), 1);
    QCOMPARE(two->Threads(), 2);
    SystemState state(2);
    state.q << 0.1, -0.2, 0.3, 0.7, 0.11, -0.05;
    state.v << 1.0, 2.0, -3.0, 0.5, -0.25, 0.125;
    ids.clear();
    const Eigen::VectorXd q1 = one->AppliedForces(0.0, state);
    QCOMPARE(int(ids.size()), 1);
    ids.clear();
    rendezvous = true;
    const Eigen::VectorXd q2 = two->AppliedForces(0.0, state);
    rendezvous = false;
    QCOMPARE(int(ids.size()), 2);  // really side by side
    QVERIFY(q1 == q2);             // bit for bit
    Eigen::MatrixXd dq1, dv1, dq2, dv2;
    one->AccelerationJacobian(0.0, state, &dq1, &dv1);
    two->AccelerationJacobian(0.0, state, &dq2, &dv2);
    QVERIFY(dq1 == dq2);
    QVERIFY(dv1 == dv2);
    QVERIFY(dq1.norm() > 0.0);
  }
};

QTEST_GUILESS_MAIN(TestWorkerPool)
#include "test_worker_pool.moc"
