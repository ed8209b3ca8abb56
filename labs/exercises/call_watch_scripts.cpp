// The scripts of numlab's watch on forbidden library calls (call_watch.hpp), as numlab writes them
// into the student's run.
#include <fmt/format.h>

#include "exercises/call_watch.hpp"

namespace numlab::exercises {

const std::string& python_watch_script() {
  static const std::string script = R"py(# numlab's watch on forbidden library calls (numlab's docs/exercises.md, "Library calls"), written
# by `numlab exercise check` for this run only. Each function that forbidden.txt (beside this file)
# names is wrapped when its module is imported: a call from outside the library itself is logged
# to $NUMLAB_CALL_LOG, and the function still does what it always does. Then the sitecustomize
# this file hides, if any, runs as usual.
import os
import sys


def _numlab_watch():
    import functools

    log_path = os.environ.get("NUMLAB_CALL_LOG")
    if not log_path:
        return
    here = os.path.dirname(os.path.abspath(__file__))
    wanted = {}
    with open(os.path.join(here, "forbidden.txt"), encoding="utf-8") as listed:
        for line in listed:
            module, _, attribute = line.strip().partition(":")
            if attribute:
                wanted.setdefault(module, []).append(attribute)
    libraries = {module.partition(".")[0] for module in wanted}
    log = os.open(log_path, os.O_WRONLY | os.O_APPEND | os.O_CREAT | os.O_CLOEXEC, 0o600)

    def record(line):
        os.write(log, (line + "\n").encode())

    def watched(name, original):
        def call(*args, **kwargs):
            caller = sys._getframe(1).f_globals.get("__name__") or ""
            if caller.partition(".")[0] not in libraries:
                record(name)
            return original(*args, **kwargs)

        functools.update_wrapper(call, original)
        call.__numlab_watched__ = True
        return call

    def wrap(module, attribute):
        *path, leaf = attribute.split(".")
        owner = module
        for part in path:
            owner = getattr(owner, part, None)
        name = module.__name__ + "." + attribute
        if isinstance(owner, type):
            raw = next((kind.__dict__[leaf] for kind in owner.__mro__ if leaf in kind.__dict__), None)
            if isinstance(raw, (classmethod, staticmethod)) and callable(raw.__func__):
                if not getattr(raw.__func__, "__numlab_watched__", False):
                    setattr(owner, leaf, type(raw)(watched(name, raw.__func__)))
                return
        original = getattr(owner, leaf, None) if owner is not None else None
        if callable(original) and not getattr(original, "__numlab_watched__", False):
            setattr(owner, leaf, watched(name, original))

    def wrap_all(module):
        for attribute in wanted.get(module.__name__, ()):
            try:
                wrap(module, attribute)
            except Exception:  # a library that changed shape: that function is not watched
                pass

    class Finder:
        @staticmethod
        def find_spec(fullname, path=None, target=None):
            if fullname not in wanted:
                return None
            for finder in sys.meta_path:
                find = getattr(finder, "find_spec", None)
                if finder is Finder or find is None:
                    continue
                spec = find(fullname, path, target)
                if spec is not None:
                    break
            else:
                return None
            exec_module = getattr(spec.loader, "exec_module", None)
            if exec_module is not None:
                def exec_and_wrap(module):
                    exec_module(module)
                    wrap_all(module)

                spec.loader.exec_module = exec_and_wrap
            return spec

    sys.meta_path.insert(0, Finder)
    for module in list(wanted):
        if module in sys.modules:
            wrap_all(sys.modules[module])
    record("+python")


def _numlab_chain():
    """Runs the sitecustomize that this one hides on sys.path (Debian's, a virtualenv's), if any."""
    import importlib.machinery
    import importlib.util

    here = os.path.dirname(os.path.abspath(__file__))
    path = [entry for entry in sys.path if os.path.abspath(entry or os.curdir) != here]
    spec = importlib.machinery.PathFinder.find_spec("sitecustomize", path)
    if spec is not None and spec.loader is not None:
        spec.loader.exec_module(importlib.util.module_from_spec(spec))


try:
    _numlab_watch()
except Exception:  # the watch must never stop the student's program: then it is not watched
    pass
del _numlab_watch
_numlab_chain()
del _numlab_chain
)py";
  return script;
}

std::string octave_watch_init(const std::vector<std::string>& functions) {
  std::string names;
  for (const std::string& function : functions) names += fmt::format("{}'{}'", names.empty() ? "" : ", ", function);
  return fmt::format(R"m(% numlab's watch on forbidden library calls (numlab's docs/exercises.md, "Library calls"), written
% by `numlab exercise check` for this run only, and run as Octave's site start-up file. Each
% function below gets a wrapper first on the path (wrappers/) that logs a call from outside
% Octave's own files to $NUMLAB_CALL_LOG and runs the original. `A \ b` does not call mldivide.m.
addpath(fullfile(fileparts(mfilename('fullpath')), 'support'));
for numlab_name = {{{}}}
  switch exist(numlab_name{{1}})
    case 5
      numlab_watched_call('--register', numlab_name{{1}}, []);
    case {{2, 3}}
      numlab_watched_call('--register', numlab_name{{1}}, str2func(numlab_name{{1}}));
  end
end
clear numlab_name
warning('off', 'Octave:shadowed-function');
addpath(fullfile(fileparts(mfilename('fullpath')), 'wrappers'));
warning('on', 'Octave:shadowed-function');
numlab_watched_call('--log', '+octave');
% The site start-up file this one stands in for.
if isempty(getenv('NUMLAB_OCTAVE_SITE_INITFILE'))
  numlab_site_file = fullfile(__octave_config_info__('localstartupfiledir'), 'octaverc');
else
  numlab_site_file = getenv('NUMLAB_OCTAVE_SITE_INITFILE');
end
if exist(numlab_site_file, 'file')
  source(numlab_site_file);
end
clear numlab_site_file
)m",
                     names);
}

const std::string& octave_watch_helper() {
  static const std::string helper = R"m(function varargout = numlab_watched_call(mode, name, varargin)
  % numlab's watch (init.m): '--register' keeps a function's original (a handle made before the
  % wrappers were on the path; [] for a built-in), '--log' logs a call made from outside Octave's own
  % files, '--call' runs the original. Locked, so `clear all` keeps what it holds.
  persistent originals log_file
  mlock();
  if isempty(originals)
    originals = struct();
    log_file = getenv('NUMLAB_CALL_LOG');
  end
  switch mode
    case '--register'
      originals.(name) = varargin{1};
    case '--log'
      stack = dbstack('-completenames');
      if numel(stack) >= 3 && strncmp(stack(3).file, OCTAVE_HOME, numel(OCTAVE_HOME))
        return;
      end
      fid = fopen(log_file, 'a');
      if fid >= 0
        fprintf(fid, '%s\n', name);
        fclose(fid);
      end
    case '--call'
      if ~isfield(originals, name)
        error('Octave:undefined-function', '''%s'' undefined', name);
      elseif isempty(originals.(name))
        [varargout{1:nargout}] = builtin(name, varargin{:});
      else
        [varargout{1:nargout}] = originals.(name)(varargin{:});
      end
  end
end
)m";
  return helper;
}

std::string octave_watch_wrapper(const std::string& function) {
  return fmt::format(R"m(function varargout = {0}(varargin)
  % numlab's watch (../init.m): logs this call, then runs Octave's {0}.
  numlab_watched_call('--log', '{0}');
  [varargout{{1:max(nargout, 1)}}] = numlab_watched_call('--call', '{0}', varargin{{:}});
end
)m",
                     function);
}

}  // namespace numlab::exercises
