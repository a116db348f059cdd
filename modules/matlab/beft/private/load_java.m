function load_java()
% Puts the client's Java classes on the Java class path: beft-matlab.jar,
% which the build compiles into BUILD/share/beft/matlab/. Taken from
% $BEFT_MATLAB_JAR, else the build folder $BEFT_BUILD_DIR, else build/ of
% this checkout; nothing is done when they are loaded already (a jar on
% the static class path, javaclasspath.txt in MATLAB).
  if ~usejava('jvm')
    error('beft:java', ['this MATLAB or Octave runs without Java, which the client needs to reach the bridge ' ...
                        '(Octave: a JDK 11 or later, Debian''s default-jdk-headless)']);
  end
  if classes_loaded()
    return;
  end
  root = fileparts(fileparts(fileparts(fileparts(fileparts(mfilename('fullpath'))))));
  build = getenv('BEFT_BUILD_DIR');
  if isempty(build)
    build = fullfile(root, 'build');
  end
  candidates = {getenv('BEFT_MATLAB_JAR'), fullfile(build, 'share', 'beft', 'matlab', 'beft-matlab.jar')};
  for i = 1:numel(candidates)
    if ~isempty(candidates{i}) && exist(candidates{i}, 'file') == 2
      file = javaObject('java.io.File', candidates{i});
      javaaddpath(char(file.getAbsolutePath()));
      return;
    end
  end
  error('beft:java', ['beft-matlab.jar not found (looked for %s): build it (cmake --build BUILD ' ...
                      '--target beft_matlab_jar, needs javac) or name it in BEFT_MATLAB_JAR'], candidates{end});
end

function yes = classes_loaded()
  try
    javaMethod('pid', 'beft.Heartbeats');
    yes = true;
  catch
    yes = false;
  end
end
