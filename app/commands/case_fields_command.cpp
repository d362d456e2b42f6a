// `filmdyn case-fields`: every field of a case file with its unit, allowed values, default and
// meaning, from the case schema (the paths `--set` and design studies take).
#include "app/commands/commands.hpp"
#include "core/io/case_fields_doc.hpp"

namespace filmdyn::cli {

Command MakeCaseFieldsCommand() {
  Command command;
  command.name = "case-fields";
  command.summary = "list every case field (dotted path for --set, unit, allowed values, default)";
  command.options = {{"markdown", "", "print the Markdown table of docs/case-file.md"}};
  command.run = [](const Args& args, Streams& streams) {
    streams.out << (args.Has("markdown") ? io::CaseFieldsMarkdown() : io::CaseFieldsText());
    return 0;
  };
  return command;
}

}  // namespace filmdyn::cli
