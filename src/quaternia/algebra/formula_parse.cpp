// The formula language of formula.h: a lexer and a recursive-descent parser over its grammar,
// which make the tree of formula_tree.h (the expansion into terms is formula_expand.cpp).
#include "quaternia/algebra/formula.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/formula_tree.h"
#include "quaternia/util/error.h"

namespace quaternia {

namespace {

using NodePtr = std::unique_ptr<const FormulaNode>;

constexpr int kMaxExponent = 64;
constexpr int kMaxNesting = 100;  // parentheses and signs: keeps recursion far from the stack's end
constexpr size_t kMaxLength = 10000;  // bounds the depth of a chain such as z + z + ... + z

[[noreturn]] void failAt(int column, const std::string& message) {
    throw FormulaError(column, "column " + std::to_string(column) + ": " + message);
}

NodePtr makeNode(FormulaNode::Kind kind, NodePtr left = nullptr, NodePtr right = nullptr) {
    auto node = std::make_unique<FormulaNode>();
    node->kind = kind;
    node->left = std::move(left);
    node->right = std::move(right);
    return node;
}

NodePtr makeConstant(const Quaternion& value) {
    auto node = std::make_unique<FormulaNode>();
    node->value = value;
    return node;
}

constexpr std::array<std::pair<FormulaFunction, std::string_view>, 15> kFunctions = {{
    {FormulaFunction::kExp, "exp"},
    {FormulaFunction::kLog, "log"},
    {FormulaFunction::kSin, "sin"},
    {FormulaFunction::kCos, "cos"},
    {FormulaFunction::kTan, "tan"},
    {FormulaFunction::kSinh, "sinh"},
    {FormulaFunction::kCosh, "cosh"},
    {FormulaFunction::kTanh, "tanh"},
    {FormulaFunction::kAsin, "asin"},
    {FormulaFunction::kAcos, "acos"},
    {FormulaFunction::kAtan, "atan"},
    {FormulaFunction::kAsinh, "asinh"},
    {FormulaFunction::kAcosh, "acosh"},
    {FormulaFunction::kAtanh, "atanh"},
    {FormulaFunction::kReciprocal, "reciprocal"},
}};

// ---- Lexer -----------------------------------------------------------------------------------

struct Token {
    enum class Kind { kNumber, kName, kSymbol, kEnd };
    Kind kind = Kind::kEnd;
    std::string_view text;
    int column = 0;
    Quaternion value;      // kNumber: a real, or an imaginary literal such as 2i
    bool integer = false;  // kNumber written with decimal digits only
};

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isNameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool isNameChar(char c) {
    return isNameStart(c) || isDigit(c);
}

Quaternion unitNamed(char name) {
    return name == 'i' ? kUnitI : name == 'j' ? kUnitJ : kUnitK;
}

class Lexer {
  public:
    explicit Lexer(std::string_view text) : text_(text) {}

    Token next() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
            ++pos_;
        Token token;
        token.column = int(pos_) + 1;
        if (pos_ >= text_.size()) return token;
        const char c = text_[pos_];
        if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(token);
        if (isNameStart(c)) {
            const size_t start = pos_;
            while (pos_ < text_.size() && isNameChar(text_[pos_]))
                ++pos_;
            token.kind = Token::Kind::kName;
            token.text = text_.substr(start, pos_ - start);
            return token;
        }
        if (std::string_view("+-*^()").find(c) == std::string_view::npos) {
            const bool printable = std::isprint(static_cast<unsigned char>(c)) != 0;
            failAt(token.column, printable ? "unexpected character '" + std::string(1, c) + "'"
                                           : std::string("unexpected non-ASCII or control "
                                                         "character (write powers as z^2)"));
        }
        token.kind = Token::Kind::kSymbol;
        token.text = text_.substr(pos_++, 1);
        return token;
    }

  private:
    char peek(size_t ahead) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    void skipDigits() {
        while (isDigit(peek(0)))
            ++pos_;
    }

    // digits [. digits] [e [+-] digits], then an optional i, j or k that is not the start of
    // a longer name: "2i" is an imaginary literal, "2z" the product 2 z.
    Token number(Token token) {
        const size_t start = pos_;
        skipDigits();
        token.integer = true;
        if (peek(0) == '.') {
            ++pos_, skipDigits();
            token.integer = false;
        }
        const size_t sign = (peek(1) == '+' || peek(1) == '-') ? 1 : 0;
        if ((peek(0) == 'e' || peek(0) == 'E') && isDigit(peek(1 + sign))) {
            pos_ += 1 + sign, skipDigits();
            token.integer = false;
        }
        const std::string_view literal = text_.substr(start, pos_ - start);
        if (peek(0) == '.')
            failAt(token.column, "malformed number '" + std::string(literal) + ".'");
        double value = 0;
        auto [end, error] = std::from_chars(literal.data(), literal.data() + literal.size(), value);
        if (error != std::errc{} || end != literal.data() + literal.size()) {
            failAt(token.column, "the number '" + std::string(literal) + "' is out of range");
        }
        token.value = Quaternion(value);
        const char suffix = peek(0);
        if ((suffix == 'i' || suffix == 'j' || suffix == 'k') && !isNameChar(peek(1))) {
            token.value = unitNamed(suffix) * value;
            token.integer = false;
            ++pos_;
        }
        token.kind = Token::Kind::kNumber;
        token.text = text_.substr(start, pos_ - start);
        return token;
    }

    std::string_view text_;
    size_t pos_ = 0;
};

// ---- Parser ----------------------------------------------------------------------------------

class Parser {
  public:
    explicit Parser(std::string_view text) : lexer_(text) { advance(); }

    NodePtr parseFormula() {
        if (token_.kind == Token::Kind::kEnd) {
            failAt(1, "the formula is empty; write a polynomial in z such as 'z^2 + c'");
        }
        NodePtr root = parseSum();
        if (atSymbol(')')) failAt(token_.column, "unmatched ')': no '(' is open");
        if (token_.kind != Token::Kind::kEnd) fail("'+', '-', '*' or end of formula");
        return root;
    }

  private:
    void advance() { token_ = lexer_.next(); }
    bool atSymbol(char c) const {
        return token_.kind == Token::Kind::kSymbol && token_.text[0] == c;
    }
    bool startsFactor() const {
        return token_.kind == Token::Kind::kNumber || token_.kind == Token::Kind::kName ||
               atSymbol('(');
    }
    [[noreturn]] void fail(const std::string& expected) const {
        const std::string found = token_.kind == Token::Kind::kEnd
                                      ? "end of formula"
                                      : "'" + std::string(token_.text) + "'";
        failAt(token_.column, "expected " + expected + " but found " + found);
    }

    // sum := product (('+' | '-') product)*
    NodePtr parseSum() {
        NodePtr left = parseProduct();
        while (atSymbol('+') || atSymbol('-')) {
            const auto kind =
                atSymbol('+') ? FormulaNode::Kind::kSum : FormulaNode::Kind::kDifference;
            advance();
            left = makeNode(kind, std::move(left), parseProduct());
        }
        return left;
    }

    // product := unary (['*'] unary)*: juxtaposition multiplies, but a '+' or '-' after a
    // factor always belongs to the sum, so "z -1" is a difference.
    NodePtr parseProduct() {
        NodePtr left = parseUnary();
        while (atSymbol('*') || startsFactor()) {
            if (atSymbol('*')) advance();
            left = makeNode(FormulaNode::Kind::kProduct, std::move(left), parseUnary());
        }
        return left;
    }

    // unary := ('+' | '-') unary | power. The power binds tighter: -z^2 is -(z^2).
    NodePtr parseUnary() {
        if (++depth_ > kMaxNesting) failAt(token_.column, "the formula is nested too deeply");
        NodePtr node;
        if (atSymbol('+') || atSymbol('-')) {
            const bool minus = atSymbol('-');
            advance();
            node = parseUnary();
            if (minus) node = makeNode(FormulaNode::Kind::kNegate, std::move(node));
        } else {
            node = parsePower();
        }
        --depth_;
        return node;
    }

    // power := primary ['^' non-negative integer | '^' ['-'] real number]: real exponents
    // (z^2.5, z^-1) are powers of the bicomplex numbers only.
    NodePtr parsePower() {
        NodePtr base = parsePrimary();
        if (!atSymbol('^')) return base;
        const int column = token_.column;
        advance();
        const bool negative = atSymbol('-');
        if (negative) advance();
        if (token_.kind != Token::Kind::kNumber || token_.value.x != 0 || token_.value.y != 0 ||
            token_.value.z != 0)
            fail("an exponent");
        if (negative || !token_.integer) {
            auto node = std::make_unique<FormulaNode>();
            node->kind = FormulaNode::Kind::kRealPower;
            node->realExponent = negative ? -token_.value.w : token_.value.w;
            node->column = column;
            node->left = std::move(base);
            advance();
            return node;
        }
        if (token_.value.w > kMaxExponent) {
            failAt(token_.column, "the exponent " + std::string(token_.text) +
                                      " is too large; the limit is " +
                                      std::to_string(kMaxExponent));
        }
        auto node = std::make_unique<FormulaNode>();
        node->kind = FormulaNode::Kind::kPower;
        node->exponent = int(token_.value.w);
        node->left = std::move(base);
        advance();
        return node;
    }

    // primary := number ['i' | 'j' | 'k'] | 'i' | 'j' | 'k' | 'z' | 'c' | '(' sum ')'
    NodePtr parsePrimary() {
        if (token_.kind == Token::Kind::kNumber) {
            NodePtr node = makeConstant(token_.value);
            advance();
            return node;
        }
        if (token_.kind == Token::Kind::kName) return parseName();
        if (!atSymbol('(')) fail("a number, i, j, k, z, c or '('");
        const int open = token_.column;
        advance();
        NodePtr inner = parseSum();
        if (!atSymbol(')')) fail("')' to close the '(' at column " + std::to_string(open));
        advance();
        return inner;
    }

    NodePtr parseName() {
        const std::string_view name = token_.text;
        NodePtr node;
        if (auto function = formulaFunctionNamed(name)) {
            // function '(' sum ')'
            const int column = token_.column;
            advance();
            if (!atSymbol('(')) fail("'(' after " + std::string(name));
            advance();
            auto call = std::make_unique<FormulaNode>();
            call->kind = FormulaNode::Kind::kFunction;
            call->function = *function;
            call->column = column;
            call->left = parseSum();
            if (!atSymbol(')')) fail("')' to close " + std::string(name) + "(");
            advance();
            return call;
        }
        if (name == "z") {
            node = makeNode(FormulaNode::Kind::kZ);
        } else if (name == "c") {
            node = makeNode(FormulaNode::Kind::kC);
        } else if (name == "i" || name == "j" || name == "k") {
            node = makeConstant(unitNamed(name[0]));
        } else {
            failAt(token_.column, "unknown name '" + std::string(name) +
                                      "'; expected z, c, i, j, k, a number, '(' or a function "
                                      "such as sin(");
        }
        advance();
        return node;
    }

    Lexer lexer_;
    Token token_;
    int depth_ = 0;
};

bool containsC(const FormulaNode* node) {
    if (node == nullptr) return false;
    return node->kind == FormulaNode::Kind::kC || containsC(node->left.get()) ||
           containsC(node->right.get());
}

}  // namespace

std::optional<FormulaFunction> formulaFunctionNamed(std::string_view name) {
    for (const auto& [function, text] : kFunctions)
        if (text == name) return function;
    return std::nullopt;
}

std::string_view formulaFunctionName(FormulaFunction function) {
    for (const auto& [f, text] : kFunctions)
        if (f == function) return text;
    return "?";
}

const FormulaNode* firstTranscendental(const FormulaNode* node) {
    if (node == nullptr) return nullptr;
    if (node->kind == FormulaNode::Kind::kFunction || node->kind == FormulaNode::Kind::kRealPower)
        return node;
    if (const FormulaNode* left = firstTranscendental(node->left.get())) return left;
    return firstTranscendental(node->right.get());
}

Formula Formula::parse(std::string_view text) {
    Formula formula;
    formula.text_ = std::string(text);
    if (text.size() > kMaxLength) {
        throw FormulaError(
            0, "the formula is longer than " + std::to_string(kMaxLength) + " characters");
    }
    formula.root_ = Parser(formula.text_).parseFormula();
    return formula;
}

bool Formula::usesC() const {
    return containsC(root_.get());
}

}  // namespace quaternia
