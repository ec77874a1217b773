#pragma once
// The answer for the type name asked last, kept for the next question. Neighbours in a
// Dictionary mostly name the same type (the BOOLs of a status record, the UDINT entries of the
// mapping objects, the USINT count of every record), so a rule walking them in order asks its
// type index once per run of a name instead of once per reference.

#include <string_view>

namespace esi::rules {

template <class Answer>
class LastNameAnswer {
public:
    // work(name) gives the answer for a name not asked last. `name` must outlive the next question.
    template <class Work>
    const Answer& get(std::string_view name, Work&& work) {
        if (!known_ || name != name_) {
            answer_ = work(name);
            name_ = name;
            known_ = true;
        }
        return answer_;
    }

private:
    bool known_ = false;
    std::string_view name_;
    Answer answer_{};
};

}  // namespace esi::rules
