function expert = beft_scene_input(expert)
%BEFT_SCENE_INPUT  Reads the ground truth of the firing's tick (the C++ SceneInput).
%   expert = beft_scene_input(expert);
%   The world publishes GT_OBJECTS when the scene changed and at keyframes,
%   and GT_VERSION every tick naming the GT_OBJECTS message in force; fire
%   gets tick k's ground truth as inputs.GT_OBJECTS, stamped with tick k's
%   utime and tick (and tick k's GT_VERSION as inputs.GT_VERSION). Without
%   any GT_VERSION heard (older logs), it is the GT_OBJECTS message of tick k.
  expert.inputs(end + 1) = struct('channel', 'GT_OBJECTS', 'type', 'beft.scene_objects_t', 'kind', 'scene', ...
                                  'capacity', 4, 'optional', false);
  expert.inputs(end + 1) = struct('channel', 'GT_VERSION', 'type', 'beft.scene_version_t', 'kind', 'tick', ...
                                  'capacity', 16, 'optional', true);
end
