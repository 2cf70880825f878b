"""Tests of contrib/core-metrics: its count of a class's data members,
member functions and friends."""

SOURCE = """
namespace x {
  template <int dim>
  class Simulator
  {
  public:
    using VectorType = int;
    Simulator(int a);
    void run();
  private:
    friend class A<dim>;
    class Services;
    struct Pair
    {
      double x, y;
      void f();
    };
    // double commented_out;
    /// A member with a comment
    double time = 0;
    VectorType u, v, a;
    std::map<int, std::pair<int, int>> map;
    std::function<void(int)> callback;
    struct Factors
    {
      double k = 1;
    } factors;
    void solve(const std::function<void()> &f,
               const VectorType *p = nullptr);
    int scheme() const
    {
      return 0;
    }
    double after_inline_function;
  };
}
"""


def test_counts(script):
    tool = script("core-metrics")
    data, functions, friends = tool.count(SOURCE)
    assert friends == 1
    # time, u, v, a, map, callback, factors, after_inline_function
    assert len(data) == 8
    # the constructor, run, solve, scheme
    assert len(functions) == 4


def test_the_repository_parses(script, capsys):
    tool = script("core-metrics")
    assert tool.main([]) == 0
    out = capsys.readouterr().out
    assert "data members" in out and "friend declarations" in out
