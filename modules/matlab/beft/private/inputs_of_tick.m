function [inputs, lacking] = inputs_of_tick(ports, tick)
% What fire gets for tick k (one field per channel read, and in
% inputs.latest the newest message of each, whatever its tick) and the
% channels the firing still waits for (lib/expert: a tick input lacks tick
% k until its message of tick k is here, unless optional and nothing was
% heard yet; the scene lacks it until its ground truth is known).
  inputs = struct();
  latest = struct();
  lacking = {};
  for i = 1:numel(ports)
    port = ports(i);
    switch port.kind
      case 'tick'
        message = message_of_tick(port, tick);
        missing = isempty(message) && ~(port.optional && isempty(port.messages));
      case 'scene'
        message = scene_of_tick(port, ports, tick);
        missing = isempty(message);
      otherwise  % latest
        message = [];
        if ~isempty(port.messages)
          message = port.messages{end};
        end
        missing = false;
    end
    inputs.(port.channel) = message;
    latest.(port.channel) = [];
    if ~isempty(port.messages)
      latest.(port.channel) = port.messages{end};
    end
    if missing
      lacking{end + 1} = port.channel; %#ok<AGROW>
    end
  end
  inputs.latest = latest;
end

% Tick k's ground truth: the GT_OBJECTS message GT_VERSION names for tick k
% (tick k's own without a GT_VERSION), stamped with tick k's utime and tick.
function scene = scene_of_tick(port, ports, tick)
  versions = ports(strcmp({ports.channel}, 'GT_VERSION'));
  version = [];
  if ~isempty(versions)
    version = message_of_tick(versions(1), tick);
  end
  if isempty(version)
    scene = message_of_tick(port, tick);
  else
    scene = message_of_tick(port, version.scene_tick);
  end
  if ~isempty(scene) && scene.tick ~= tick
    scene.utime = version.utime;
    scene.tick = tick;
  end
end
