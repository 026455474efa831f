// A party: one way to answer a query kind besides the library's own call (the library's other
// ways, and each second opinion), declared with its name, its band and its call together.
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "harness/model/band.h"
#include "harness/model/answer.h"

namespace cc::harness {

/// A party that answers inputs of type In. Its call returns what it said (status, answer,
/// detail); the party's name and band are filled in when it is asked. The library's own parties
/// are named "library.<how>" and take the library's band for the kind.
template <class In>
struct Party {
  std::string name;
  Band band;
  std::function<Opinion(const In&)> ask;
};

/// What a party said: an answer, a hit, not applicable (and why), or a failure (and what).
inline Opinion said(Opinion::Status status, Answer answer, std::string detail) {
  Opinion o;
  o.status = status;
  o.answer = std::move(answer);
  o.detail = std::move(detail);
  return o;
}
inline Opinion answered(Answer answer) { return said(Opinion::Status::answered, std::move(answer), ""); }
inline Opinion answered(bool hit) { return answered(Answer::of(hit)); }
inline Opinion not_applicable(std::string why) { return said(Opinion::Status::not_applicable, {}, std::move(why)); }
inline Opinion failed(std::string what) { return said(Opinion::Status::failed, {}, std::move(what)); }
/// Cut off at its time limit (`what`: which limit), never an answer (Opinion::Status::timed_out).
inline Opinion timed_out(std::string what) { return said(Opinion::Status::timed_out, {}, std::move(what)); }

/// Every party's opinion of `in`, in order, each with its name and band; a C++ exception from a
/// party's call is a failed opinion.
template <class In>
std::vector<Opinion> ask_parties(const std::vector<Party<In>>& parties, const In& in) {
  std::vector<Opinion> out;
  for (const Party<In>& p : parties) {
    Opinion o;
    try {
      o = p.ask(in);
    } catch (const std::exception& e) {
      o = failed(std::string("exception: ") + e.what());
    } catch (...) {
      o = failed("exception of unknown type");
    }
    o.party = p.name;
    o.band = p.band;
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace cc::harness
