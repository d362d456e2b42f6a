#include "ui/case_editor/case_document.hpp"

#include <QDir>
#include <QFileInfo>
#include <QUndoCommand>
#include <algorithm>
#include <cmath>

#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"
#include "ui/case_editor/case_json.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

class CaseSnapshotCommand : public QUndoCommand {
 public:
  CaseSnapshotCommand(CaseDocument* document, engine::EngineCase before, engine::EngineCase after,
                      const QString& text, int merge_key)
      : QUndoCommand(text),
        document_(document),
        before_(std::move(before)),
        after_(std::move(after)),
        merge_key_(merge_key) {}

  void undo() override { document_->apply(before_); }
  void redo() override { document_->apply(after_); }
  int id() const override { return merge_key_; }
  bool mergeWith(const QUndoCommand* other) override {
    if (other->id() != id()) return false;
    after_ = static_cast<const CaseSnapshotCommand*>(other)->after_;
    return true;
  }

 private:
  CaseDocument* document_;
  engine::EngineCase before_;
  engine::EngineCase after_;
  int merge_key_;
};

namespace {

// An edit makes the "assumed" note of every field it changes stale: the value is the user's now,
// so the note goes with the edit (undo brings it back) and is neither shown nor saved. The
// columns of a list table go together: a change to any of them (a cell, a row, an import) drops
// the notes of all (the skirt profile's y and h, say).
void DropStaleAssumptions(const engine::EngineCase& before, engine::EngineCase* after) {
  if (after->assumed.empty()) return;
  std::vector<std::string> stale;
  for (const engine::CaseField& f : engine::CaseSchema()) {
    if (f.kind == engine::FieldKind::kNumberList || f.SameValue(before, *after)) continue;
    stale.push_back(f.path);
  }
  for (const CaseListTable& table : CaseListTables()) {
    const bool changed =
        std::any_of(table.columns.begin(), table.columns.end(),
                    [&](const engine::CaseField* f) { return !f->SameValue(before, *after); });
    if (!changed) continue;
    for (const engine::CaseField* f : table.columns) stale.push_back(f->path);
  }
  for (const std::string& path : stale) after->assumed.erase(path);
}

}  // namespace

CaseDocument::CaseDocument(QObject* parent) : QObject(parent) {
  connect(&undo_stack_, &QUndoStack::cleanChanged, this,
          [this](bool clean) { emit modifiedChanged(!clean); });
  apply(case_);
}

CaseDocument::~CaseDocument() {
  // ~QUndoStack clears the stack and emits cleanChanged; by then this document's own members
  // are going and its parent (the main window) may be half destroyed.
  undo_stack_.blockSignals(true);
  blockSignals(true);
}

void CaseDocument::edit(const engine::EngineCase& new_case, const QString& description,
                        int merge_key) {
  engine::EngineCase after = new_case;
  DropStaleAssumptions(case_, &after);
  undo_stack_.push(new CaseSnapshotCommand(this, case_, std::move(after), description, merge_key));
}

void CaseDocument::setParameter(const std::string& path, double si_value) {
  const CaseParameter* p = FindCaseParameter(path);
  Q_ASSERT(p != nullptr && !p->choice && !p->text);
  if (p == nullptr || p->choice || p->text) return;  // set by name (setChoice, setText)
  engine::EngineCase next = case_;
  p->set(next, si_value);
  // Merge repeated edits of the same cell into one undo step.
  const int key = 1000 + int(p - CaseParameters().data());
  edit(next, QObject::tr("Edit %1").arg(p->label), key);
}

bool CaseDocument::setChoice(const std::string& path, const std::string& name) {
  const CaseParameter* p = FindCaseParameter(path);
  if (p == nullptr || !p->choice) return false;
  const std::vector<std::string>& choices = p->field->choices;
  const auto it = std::find(choices.begin(), choices.end(), name);
  if (it == choices.end()) return false;
  engine::EngineCase next = case_;
  p->field->set_choice(next, int(it - choices.begin()));
  // A choice is one deliberate step: never merged with the next one.
  const std::string& who = p->field->symbol.empty() ? p->field->label : p->field->symbol;
  edit(
      next,
      QObject::tr("Set %1 to “%2”").arg(QString::fromStdString(who), QString::fromStdString(name)));
  return true;
}

std::string CaseDocument::caseDirectory() const {
  return file_path_.isEmpty() ? std::string() : QFileInfo(file_path_).absolutePath().toStdString();
}

bool CaseDocument::setText(const std::string& path, const std::string& value) {
  const CaseParameter* p = FindCaseParameter(path);
  if (p == nullptr || !p->text) return false;
  engine::EngineCase next = case_;
  std::string& text = p->field->text(next);
  if (text == value) return true;
  text = value;
  edit(next, QObject::tr("Set %1").arg(p->label));
  return true;
}

void CaseDocument::apply(const engine::EngineCase& engine_case) {
  case_ = engine_case;
  issues_ = ValidateCase(case_);
  const QString blocker = QString::fromStdString(RunBlocker(case_, issues_));
  emit caseChanged();
  if (blocker != run_blocker_ || blocker.isEmpty()) {
    run_blocker_ = blocker;
    emit validityChanged(run_blocker_);
  }
}

void CaseDocument::reset(const engine::EngineCase& engine_case, const QString& file_path) {
  undo_stack_.clear();
  apply(engine_case);
  file_path_ = file_path;
  emit filePathChanged(file_path_);
  emit modifiedChanged(false);
}

bool CaseDocument::save(const QString& path, QString* error) {
  // Saved in another folder: relative file names (compliance files, pressure CSVs) are made to
  // name the same files from there, as an edit of its own (undo gives back the old names).
  const std::string from =
      file_path_.isEmpty() ? QDir::currentPath().toStdString() : caseDirectory();
  engine::EngineCase moved = case_;
  const bool rebased =
      io::RebaseCaseFiles(&moved, from, QFileInfo(path).absolutePath().toStdString()) > 0;
  if (rebased)
    edit(moved, QObject::tr("File names made relative to %1").arg(QFileInfo(path).absolutePath()));
  if (!SaveCaseFile(case_, path, error)) {
    if (rebased) undo_stack_.undo();  // not saved there: the names stay as they were
    return false;
  }
  undo_stack_.setClean();
  if (file_path_ != path) {
    file_path_ = path;
    emit filePathChanged(file_path_);
  }
  return true;
}

bool CaseDocument::load(const QString& path, QString* error) {
  engine::EngineCase loaded;
  if (!LoadCaseFile(path, &loaded, error, &load_notes_)) return false;
  reset(loaded, path);
  return true;
}

}  // namespace filmdyn::ui
