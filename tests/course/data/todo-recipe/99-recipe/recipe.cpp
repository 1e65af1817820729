// A student's file whose TODO dictates the code (course_todo_check_finds_a_recipe): eight TODO
// lines for three solution lines, a ratio scripts/check-todos.sh must refuse.
namespace ps {

float recipe(float a, float b) {
    //! TODO(99) Compute the sum:
    //!          1. call first(a) and keep it in x;
    //!          2. call second(b) and keep it in y;
    //!          3. add x and y;
    //!          4. multiply by 0.5;
    //!          5. return it.
    //!          Pitfall: do it in this order.
    //! STUB return PS_TODO("lesson 99: recipe", 0.0f);
    //! BEGIN
    const float x = a;
    const float y = b;
    return 0.5f * (x + y);
    //! END
}

}  // namespace ps
