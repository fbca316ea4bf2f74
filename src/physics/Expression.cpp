#include "physics/Expression.hpp"

#include <cmath>
#include <stdexcept>

#include <muParser.h>

namespace unilag
{

struct Expression::Impl
{
    mu::Parser parser;
    double x = 0.0, y = 0.0, z = 0.0, r = 0.0, t = 0.0;
};

Expression::Expression(const std::string& text) : impl_(std::make_unique<Impl>())
{
    try
    {
        impl_->parser.DefineVar("x", &impl_->x);
        impl_->parser.DefineVar("y", &impl_->y);
        impl_->parser.DefineVar("z", &impl_->z);
        impl_->parser.DefineVar("r", &impl_->r);
        impl_->parser.DefineVar("t", &impl_->t);
        impl_->parser.SetExpr(text);
        impl_->parser.Eval(); // compile now, so a syntax error surfaces while reading the scene
    }
    catch (const mu::Parser::exception_type& e)
    {
        throw std::invalid_argument("cannot parse expression '" + text + "': " + e.GetMsg());
    }
}

Expression::~Expression() = default;

double Expression::operator()(double x, double y, double z, double t)
{
    impl_->t = t;
    impl_->x = x;
    impl_->y = y;
    impl_->z = z;
    impl_->r = std::sqrt(x * x + y * y + z * z);
    return impl_->parser.Eval();
}

} // namespace unilag
