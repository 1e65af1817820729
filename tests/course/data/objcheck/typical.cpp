// What a student's file may well use of the standard library, compiled as a lesson's file is:
// the grader's object check must refuse none of it (CTest course_grade_object_check_typical).
// Containers, strings, string streams and printing to the terminal, <random>, exceptions and
// typeinfo, std::thread and locks, OpenMP, math and complex numbers, static and thread-local
// objects; nothing of it is called by a test.
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <iostream>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <variant>
#include <vector>
#include <deque>
#include <array>
#include <atomic>
#include <bitset>
#include <condition_variable>
#include <queue>
#include <charconv>

static std::mutex m;
double work(const std::vector<double>& v, const std::string& name) {
    std::lock_guard<std::mutex> lock(m);
    std::map<std::string, int> counts;
    counts[name]++;
    std::unordered_map<int, double> um;
    um[3] = 2.0;
    std::set<int> s{3, 1, 2};
    std::unordered_set<std::string> us{name};
    std::list<int> l{1, 2};
    l.push_back(3);
    std::deque<int> d{1};
    d.push_front(2);
    std::priority_queue<double> pq;
    for (double x : v) pq.push(x);
    std::ostringstream out;
    out << std::fixed << std::setprecision(3) << v.size() << " " << name << std::endl;
    std::cout << out.str() << 1.5f << ' ' << 2 << std::endl;
    std::cerr << "dbg " << std::hex << 255 << "\n";
    std::printf("%g\n", std::sqrt(2.0));
    std::fprintf(stderr, "x\n");
    std::istringstream in("1 2 3");
    int a;
    in >> a;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    double r = u(rng);
    std::random_device rd;
    (void)rd;
    std::normal_distribution<double> nd;
    r += nd(rng);
    auto t0 = std::chrono::steady_clock::now();
    (void)t0;
    std::vector<double> w(v);
    std::sort(w.begin(), w.end());
    std::nth_element(w.begin(), w.begin(), w.end());
    double sum = std::accumulate(w.begin(), w.end(), 0.0);
    std::complex<double> c(1, 2);
    c *= c;
    sum += std::abs(c);
    std::optional<double> o = sum;
    std::variant<int, double> var = 2.0;
    std::function<double(double)> f = [](double x) { return std::exp(x) + std::pow(x, 2.5) + std::atan2(x, 1.0); };
    sum += f(*o) + std::get<double>(var) + std::stod("1.5") + std::stoi("3") + std::to_string(r).size() +
           std::to_string(3).size();
    std::unique_ptr<int> p = std::make_unique<int>(3);
    std::shared_ptr<int> sp = std::make_shared<int>(4);
    std::bitset<8> bs(5);
    sum += bs.count() + *p + *sp;
    std::atomic<int> at{0};
    at++;
    std::thread th([&] { at++; });
    th.join();
    std::condition_variable cv;
    cv.notify_all();
    char buf[32];
    auto res = std::to_chars(buf, buf + 32, 42);
    (void)res;
    assert(sum > 0);
    if (sum < 0) throw std::runtime_error("negative: " + name);
    if (v.empty()) throw std::invalid_argument("empty");
    try {
        std::vector<int> q(3);
        (void)q.at(5);
    } catch (const std::out_of_range& e) { std::cerr << e.what(); }
    return sum + counts.size() + um.size() + s.size() + us.size() + l.size() + d.size() + a;
}
struct Base {
    virtual ~Base() = default;
    virtual double g() const = 0;
};
struct Derived : Base {
    double g() const override { return 1; }
};
double poly(const Base& b) { return dynamic_cast<const Derived*>(&b) ? b.g() : 0; }
static const std::vector<double> kTable = {1, 2, 3};
double table(int i) {
    static const std::map<int, double> lazy = {{1, 2.0}};
    thread_local std::vector<int> tl;
    tl.push_back(i);
    return kTable[i] + lazy.at(1);
}
double par(const std::vector<double>& v) {
    double s = 0;
#pragma omp parallel for reduction(+ : s)
    for (int i = 0; i < (int)v.size(); ++i) s += v[i];
    return s;
}
