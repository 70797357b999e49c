// json_lite.h: a small JSON reader for the tests (the project writes JSON, it never reads it).
#pragma once

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace jsonlite {

struct Value {
    enum Kind { NUL, BOOL, NUMBER, STRING, ARRAY, OBJECT } kind = NUL;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<Value> array;
    std::map<std::string, Value> object;

    const Value& operator[](const std::string& key) const {
        auto it = object.find(key);
        if (kind != OBJECT || it == object.end()) throw std::runtime_error("no key " + key);
        return it->second;
    }
    const Value& operator[](size_t i) const { return array.at(i); }
    bool has(const std::string& key) const { return object.count(key) > 0; }
    size_t size() const { return kind == ARRAY ? array.size() : object.size(); }
};

class Parser {
  public:
    explicit Parser(const std::string& text) : mText(text) {}
    Value parse() {
        Value v = value();
        skip();
        if (mPos != mText.size()) throw std::runtime_error("trailing characters");
        return v;
    }

  private:
    void skip() {
        while (mPos < mText.size() && std::isspace(static_cast<unsigned char>(mText[mPos]))) ++mPos;
    }
    char peek() {
        skip();
        if (mPos >= mText.size()) throw std::runtime_error("unexpected end");
        return mText[mPos];
    }
    void expect(char c) {
        if (peek() != c) throw std::runtime_error(std::string("expected ") + c);
        ++mPos;
    }
    Value value() {
        char c = peek();
        Value v;
        if (c == '{') {
            v.kind = Value::OBJECT;
            ++mPos;
            if (peek() == '}') {
                ++mPos;
                return v;
            }
            for (;;) {
                std::string key = str();
                expect(':');
                v.object[key] = value();
                if (peek() == ',') {
                    ++mPos;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            v.kind = Value::ARRAY;
            ++mPos;
            if (peek() == ']') {
                ++mPos;
                return v;
            }
            for (;;) {
                v.array.push_back(value());
                if (peek() == ',') {
                    ++mPos;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.kind = Value::STRING;
            v.string = str();
            return v;
        }
        if (mText.compare(mPos, 4, "true") == 0) {
            mPos += 4;
            v.kind = Value::BOOL;
            v.boolean = true;
            return v;
        }
        if (mText.compare(mPos, 5, "false") == 0) {
            mPos += 5;
            v.kind = Value::BOOL;
            return v;
        }
        if (mText.compare(mPos, 4, "null") == 0) {
            mPos += 4;
            return v;
        }
        char* end = nullptr;
        v.number = std::strtod(mText.c_str() + mPos, &end);
        if (end == mText.c_str() + mPos) throw std::runtime_error("bad value");
        mPos = static_cast<size_t>(end - mText.c_str());
        v.kind = Value::NUMBER;
        return v;
    }
    std::string str() {
        expect('"');
        std::string out;
        while (mPos < mText.size() && mText[mPos] != '"') {
            char c = mText[mPos++];
            if (c == '\\') {
                char e = mText[mPos++];
                if (e == 'n')
                    out += '\n';
                else if (e == 't')
                    out += '\t';
                else if (e == 'u') {
                    out += '?';
                    mPos += 4;
                } else
                    out += e;
            } else {
                out += c;
            }
        }
        ++mPos;
        return out;
    }
    const std::string& mText;
    size_t mPos = 0;
};

inline Value parse(const std::string& text) { return Parser(text).parse(); }

}  // namespace jsonlite
