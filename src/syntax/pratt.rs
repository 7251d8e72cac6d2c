//! Operator precedence of the flat `expr` rule (pest's Pratt parser) and the operator names.
//!
//! The grammar lists operands and operators in a row; this table turns the row into a tree.
//! Levels from lowest to highest (docs/language.md §5):
//! `||` · `&&` · comparisons · `step` · ranges · `>>` · `|` · `+ -` · `&` · `* / % div` ·
//! prefix `-` `!` · `**` (right-associative, so `-2 ** 2` is `-(2 ** 2)`) · call, index, member,
//! record call and `with`.

use pest::pratt_parser::{Assoc, ConstPrattParser, Op};

use crate::syntax::ast::BinOp;
use crate::syntax::grammar::Rule;

/// The precedence table.
pub(crate) static PRATT: ConstPrattParser<Rule, 19> = ConstPrattParser::new_const([
    (Op::infix(Rule::or_op, Assoc::Left), true),
    (Op::infix(Rule::and_op, Assoc::Left), true),
    (Op::infix(Rule::cmp_op, Assoc::Left), true),
    (Op::infix(Rule::step_kw, Assoc::Left), true),
    (Op::infix(Rule::range_op, Assoc::Left), true),
    (Op::infix(Rule::then_op, Assoc::Left), true),
    (Op::infix(Rule::union_op, Assoc::Left), true),
    (Op::infix(Rule::add_op, Assoc::Left), true),
    (Op::infix(Rule::add_line_op, Assoc::Left), false),
    (Op::infix(Rule::inter_op, Assoc::Left), true),
    (Op::infix(Rule::mul_op, Assoc::Left), true),
    (Op::prefix(Rule::unary_op), true),
    (Op::infix(Rule::pow_op, Assoc::Right), true),
    (Op::postfix(Rule::call_args), true),
    (Op::postfix(Rule::index), false),
    (Op::postfix(Rule::member), false),
    (Op::postfix(Rule::record_arg), false),
    (Op::postfix(Rule::empty_record_arg), false),
    (Op::postfix(Rule::with_suffix), false),
]);

/// True for the rules of suffixes: calls, indexing, members, record arguments, `with`.
pub(crate) fn is_suffix(rule: Rule) -> bool {
    matches!(
        rule,
        Rule::call_args
            | Rule::index
            | Rule::member
            | Rule::record_arg
            | Rule::empty_record_arg
            | Rule::with_suffix
    )
}

/// True for the rules of binary operators.
pub(crate) fn is_infix(rule: Rule) -> bool {
    matches!(
        rule,
        Rule::or_op
            | Rule::and_op
            | Rule::cmp_op
            | Rule::step_kw
            | Rule::range_op
            | Rule::then_op
            | Rule::union_op
            | Rule::add_op
            | Rule::add_line_op
            | Rule::inter_op
            | Rule::mul_op
            | Rule::pow_op
    )
}

/// The binary operator written as `text` (`step` and ranges are not `BinOp`s).
pub(crate) fn bin_op(text: &str) -> Option<BinOp> {
    Some(match text {
        "||" => BinOp::Or,
        "&&" => BinOp::And,
        "==" => BinOp::Eq,
        "!=" => BinOp::Ne,
        "<" => BinOp::Lt,
        "<=" => BinOp::Le,
        ">" => BinOp::Gt,
        ">=" => BinOp::Ge,
        ">>" => BinOp::Then,
        "|" => BinOp::Union,
        "+" => BinOp::Add,
        "-" => BinOp::Sub,
        "&" => BinOp::Inter,
        "*" => BinOp::Mul,
        "/" => BinOp::Div,
        "%" => BinOp::Rem,
        "div" => BinOp::IntDiv,
        "**" => BinOp::Pow,
        _ => return None,
    })
}
