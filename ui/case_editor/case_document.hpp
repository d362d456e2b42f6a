#pragma once
/// @file The case being edited: the EngineCase (SI), its undo stack, file name, modified flag and
/// validation issues. Every edit goes through an undo command that swaps whole case snapshots
/// (a case is a few kB), so undo/redo is exact for scalars, tables and curves alike.
#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include "core/engine/engine_case.hpp"
#include "ui/case_editor/case_validation.hpp"

namespace filmdyn::ui {

class CaseDocument : public QObject {
  Q_OBJECT

 public:
  explicit CaseDocument(QObject* parent = nullptr);
  /// Quiet: the undo stack's clearing on destruction emits no signal (listeners may already be
  /// half destroyed, e.g. the main window that owns this document).
  ~CaseDocument() override;

  const engine::EngineCase& engineCase() const { return case_; }
  QUndoStack* undoStack() { return &undo_stack_; }
  const CaseIssues& issues() const { return issues_; }
  /// Why Run is not possible now (empty when it is).
  QString runBlocker() const { return run_blocker_; }

  /// Replaces the case through an undoable command. merge_key > 0 merges consecutive edits with
  /// the same key (typing in one cell several times is one undo step). The "assumed" notes of
  /// the fields the edit changes are dropped with it (a list table's columns together): the
  /// values are the user's now; undo brings the notes back.
  void edit(const engine::EngineCase& new_case, const QString& description, int merge_key = -1);
  /// Sets one scalar parameter (SI) by dotted path; undoable.
  void setParameter(const std::string& path, double si_value);
  /// Sets a choice parameter (CaseParameter::choice) by dotted path to one of its names; undoable,
  /// one undo step per change. False (the case unchanged) when `name` is not one of its choices.
  bool setChoice(const std::string& path, const std::string& name);
  /// Sets a text parameter (CaseParameter::text); false when `path` is not one.
  bool setText(const std::string& path, const std::string& value);

  QString filePath() const { return file_path_; }
  /// The saved case file's folder, where the files the case names by a relative path are found
  /// (empty for an unsaved case: the working directory).
  std::string caseDirectory() const;
  bool isModified() const { return !undo_stack_.isClean(); }

  /// Starts a new document (no undo history, unmodified).
  void reset(const engine::EngineCase& engine_case, const QString& file_path = {});
  bool save(const QString& path, QString* error);
  bool load(const QString& path, QString* error);
  /// The case reader's notes on the last load (e.g. an older key read as its replacement).
  QStringList loadNotes() const { return load_notes_; }

 signals:
  void caseChanged();
  void validityChanged(const QString& run_blocker);
  void filePathChanged(const QString& path);
  void modifiedChanged(bool modified);

 private:
  friend class CaseSnapshotCommand;
  void apply(const engine::EngineCase& engine_case);

  engine::EngineCase case_;
  QUndoStack undo_stack_;
  CaseIssues issues_;
  QString run_blocker_;
  QString file_path_;
  QStringList load_notes_;
};

}  // namespace filmdyn::ui
