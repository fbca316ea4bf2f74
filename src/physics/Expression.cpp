#include "physics/Expression.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

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
        int values = 0;
        impl_->parser.Eval(values); // compile now, so a syntax error surfaces while reading the scene
        // muParser takes "1,5" as two results and "x = 3" as an assignment, and returns the last value: a decimal
        // comma ran as 5
        if (values != 1)
            throw std::invalid_argument("'" + text + "' holds " + std::to_string(values) +
                                        " comma-separated values where one belongs (a decimal point, not a comma)");
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '=' && (i == 0 || std::string("=!<>").find(text[i - 1]) == std::string::npos) &&
                (i + 1 == text.size() || text[i + 1] != '='))
                throw std::invalid_argument("'" + text + "' assigns ('=') where a value belongs ('==' compares)");
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
